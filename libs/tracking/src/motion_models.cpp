#include "kestrel/tracking/motion_models.hpp"

#include <algorithm>
#include <cmath>

namespace kestrel::tracking {

std::string_view motion_model_name(MotionModel model) {
  switch (model) {
    case MotionModel::constant_velocity:
      return "cv";
    case MotionModel::constant_acceleration:
      return "ca";
    case MotionModel::coordinated_turn:
      return "ct";
  }
  return "?";
}

double turn_rate(const State& x, double min_speed, double max_rate) {
  const double vx = x(index(0, 1)), vy = x(index(1, 1)), ax = x(index(0, 2)), ay = x(index(1, 2));
  const double speed2 = vx * vx + vy * vy;
  if (speed2 < min_speed * min_speed) return 0.0;
  return std::clamp((vx * ay - vy * ax) / speed2, -max_rate, max_rate);
}

namespace {

Covariance constant_velocity_transition(double dt) {
  Covariance F = Covariance::Zero();
  for (int a = 0; a < 3; ++a) {
    F(index(a, 0), index(a, 0)) = 1.0;
    F(index(a, 0), index(a, 1)) = dt;
    F(index(a, 1), index(a, 1)) = 1.0;
  }
  return F;
}

Covariance coordinated_turn_transition(const State& x, double dt) {
  // The horizontal acceleration turns at w with the velocity (a(s) = R(w s) a0): integrated, with
  // R = R(w dt) and J the quarter turn,
  //   a = R a0,  v = v0 + A_v a0,  p = p0 + v0 dt + A_p a0,
  //   A_v = -(R - I) J / w,  A_p = -(R - I) / w^2 + J dt / w,
  // which tend to dt I and dt^2/2 I (constant acceleration) as w -> 0. A centripetal a0 = w J v0
  // keeps the speed: v = R v0, the circle.
  Covariance F = transition(dt);  // the vertical axis: constant acceleration
  const double w = turn_rate(x);
  const Eigen::Matrix2d I = Eigen::Matrix2d::Identity();
  Eigen::Matrix2d J;
  J << 0.0, -1.0, 1.0, 0.0;
  Eigen::Matrix2d R;
  R << std::cos(w * dt), -std::sin(w * dt), std::sin(w * dt), std::cos(w * dt);
  Eigen::Matrix2d Av, Ap;
  if (std::abs(w) > 1e-4) {
    Av = -(R - I) * J / w;
    Ap = -(R - I) / (w * w) + J * dt / w;
  } else {  // the series to second order in w dt
    Av = dt * I + (w * dt * dt / 2.0) * J;
    Ap = (dt * dt / 2.0) * I + (w * dt * dt * dt / 6.0) * J;
  }
  const int p[2] = {index(0, 0), index(1, 0)}, v[2] = {index(0, 1), index(1, 1)}, a[2] = {index(0, 2), index(1, 2)};
  for (int i = 0; i < 2; ++i)
    for (int k = 0; k < 2; ++k) {
      F(p[i], a[k]) = Ap(i, k);
      F(v[i], a[k]) = Av(i, k);
      F(a[i], a[k]) = R(i, k);
    }
  return F;
}

}  // namespace

Covariance model_transition(MotionModel model, const State& x, double dt) {
  switch (model) {
    case MotionModel::constant_velocity:
      return constant_velocity_transition(dt);
    case MotionModel::coordinated_turn:
      return coordinated_turn_transition(x, dt);
    case MotionModel::constant_acceleration:
      break;
  }
  return transition(dt);
}

Covariance model_process_noise(MotionModel model, double dt, double q) {
  if (model != MotionModel::constant_velocity) return process_noise(dt, q);
  Covariance Q = Covariance::Zero();
  const double block[2][2] = {{dt * dt * dt / 3.0, dt * dt / 2.0}, {dt * dt / 2.0, dt}};
  for (int a = 0; a < 3; ++a)
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) Q(index(a, i), index(a, j)) = q * block[i][j];
  return Q;
}

}  // namespace kestrel::tracking
