#include "kestrel/tracking/constant_acceleration.hpp"

#include <Eigen/Cholesky>

namespace kestrel::tracking {

Covariance transition(double dt) {
  Covariance F = Covariance::Identity();
  for (int a = 0; a < 3; ++a) {
    F(index(a, 0), index(a, 1)) = dt;
    F(index(a, 0), index(a, 2)) = dt * dt / 2.0;
    F(index(a, 1), index(a, 2)) = dt;
  }
  return F;
}

Covariance process_noise(double dt, double q) {
  const double dt2 = dt * dt, dt3 = dt2 * dt, dt4 = dt3 * dt, dt5 = dt4 * dt;
  const double block[3][3] = {{dt5 / 20, dt4 / 8, dt3 / 6}, {dt4 / 8, dt3 / 3, dt2 / 2}, {dt3 / 6, dt2 / 2, dt}};
  Covariance Q = Covariance::Zero();
  for (int a = 0; a < 3; ++a)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) Q(index(a, i), index(a, j)) = q * block[i][j];
  return Q;
}

Covariance initial_covariance(double p) {
  Covariance P = Covariance::Zero();
  const double variances[3] = {1.0 * 1.0, 30.0 * 30.0, 5.5 * 5.5};
  for (int a = 0; a < 3; ++a)
    for (int k = 0; k < 3; ++k) P(index(a, k), index(a, k)) = p * variances[k];
  return P;
}

Eigen::Matrix<double, 3, 9> measurement_matrix() {
  Eigen::Matrix<double, 3, 9> H = Eigen::Matrix<double, 3, 9>::Zero();
  H.leftCols<3>().setIdentity();
  return H;
}

ConstantAccelerationKalman ConstantAccelerationKalman::start(const Eigen::Vector3d& z, double p) {
  ConstantAccelerationKalman k;
  k.x.head<3>() = z;
  k.P = initial_covariance(p);
  return k;
}

void ConstantAccelerationKalman::predict(double dt, double q) { predict(transition(dt), process_noise(dt, q)); }

void ConstantAccelerationKalman::predict(const Covariance& F, const Covariance& Q) {
  x = F * x;
  P = F * P * F.transpose() + Q;
}

Eigen::Matrix3d ConstantAccelerationKalman::innovation_covariance(double r) const {
  return P.topLeftCorner<3, 3>() + r * Eigen::Matrix3d::Identity();
}

void ConstantAccelerationKalman::update(const Eigen::Vector3d& z, double r) {
  const auto H = measurement_matrix();
  const Eigen::Matrix3d S = innovation_covariance(r);
  // K = P H^T S^-1, computed as a solve with the symmetric S.
  const Eigen::Matrix<double, 9, 3> K = S.ldlt().solve(H * P).transpose();
  x += K * (z - H * x);
  // Joseph form: stays symmetric and positive definite.
  const Covariance I_KH = Covariance::Identity() - K * H;
  P = I_KH * P * I_KH.transpose() + K * (r * Eigen::Matrix3d::Identity()) * K.transpose();
}

}  // namespace kestrel::tracking
