#pragma once
// A target's predicted motion from the aim's world-frame estimate.
#include <Eigen/Core>

namespace kestrel::guidance {

/// Position, velocity and acceleration now (world), and the position's covariance.
struct TargetMotion {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d acceleration = Eigen::Vector3d::Zero();
  Eigen::Matrix3d position_covariance = Eigen::Matrix3d::Zero();

  /// Where the target will be tau seconds from now, at constant acceleration.
  Eigen::Vector3d at(double tau) const { return position + velocity * tau + 0.5 * acceleration * tau * tau; }
  Eigen::Vector3d velocity_at(double tau) const { return velocity + acceleration * tau; }
};

}  // namespace kestrel::guidance
