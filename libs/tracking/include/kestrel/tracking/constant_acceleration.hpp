#pragma once
// The 3D constant-acceleration motion model of the paper's section 2.3, as a linear Kalman
// filter. The state is [x y z vx vy vz ax ay az]; the measurement is the position.
//
//   F: per axis [[1, dt, dt^2/2], [0, 1, dt], [0, 0, 1]]
//   Q: the discrete white-noise-jerk model, per axis q * [[dt^5/20, dt^4/8, dt^3/6],
//                                                        [dt^4/8,  dt^3/3, dt^2/2],
//                                                        [dt^3/6,  dt^2/2, dt    ]]
//   R = r I3;  P0 = p diag(1^2, 30^2, 5.5^2) per axis (1 m, 30 m/s, 5.5 m/s^2)
#include <Eigen/Core>

namespace kestrel::tracking {

using State = Eigen::Matrix<double, 9, 1>;
using Covariance = Eigen::Matrix<double, 9, 9>;

/// The state index of axis a (0..2) and derivative k (0 position, 1 velocity, 2 acceleration).
constexpr int index(int axis, int derivative) { return 3 * derivative + axis; }

Covariance transition(double dt);
Covariance process_noise(double dt, double q);
Covariance initial_covariance(double p);
Eigen::Matrix<double, 3, 9> measurement_matrix();

struct ConstantAccelerationKalman {
  State x = State::Zero();
  Covariance P = Covariance::Identity();

  /// Starts at the measured position, at rest, with P0 = p diag(1, 900, 30.25).
  static ConstantAccelerationKalman start(const Eigen::Vector3d& z, double p);

  void predict(double dt, double q);
  /// The same for any linear model: x = F x, P = F P F^T + Q (kestrel/tracking/motion_models.hpp).
  void predict(const Covariance& F, const Covariance& Q);
  /// Innovation covariance S = H P H^T + r I for the current P.
  Eigen::Matrix3d innovation_covariance(double r) const;
  void update(const Eigen::Vector3d& z, double r);

  Eigen::Vector3d position() const { return x.head<3>(); }
};

}  // namespace kestrel::tracking
