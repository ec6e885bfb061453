#include "motion_axis.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace kestrel::aim {

namespace {
// An axis is clear when the target moves along it at least twice as fast as across it (in root
// mean square), and at 1 m/s or more: a hovering or circling target has none worth flying round to.
constexpr double kClearRatio = 4.0;   // of the mean squared speeds
constexpr double kLeastSpeed2 = 1.0;  // (m/s)^2
}  // namespace

void MotionAxis::update(const Eigen::Vector3d& velocity, double dt) {
  if (!velocity.allFinite()) return;
  const Eigen::Vector2d v = velocity.head<2>();
  const double w = time_constant_s_ > 0.0 ? std::min(1.0, std::max(0.0, dt) / time_constant_s_) : 1.0;
  moment_ = (1.0 - w) * moment_ + w * v * v.transpose();
}

std::optional<Eigen::Vector2d> MotionAxis::axis(const Eigen::Vector2d& bearing) const {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(moment_);
  const Eigen::Vector2d lambda = eigen.eigenvalues();  // ascending
  if (lambda(1) < kLeastSpeed2 || lambda(1) < kClearRatio * std::max(0.0, lambda(0))) return std::nullopt;
  Eigen::Vector2d axis = eigen.eigenvectors().col(1);
  if (axis.dot(bearing) < 0.0) axis = -axis;
  return axis;
}

Eigen::Vector2d approach_direction(const Eigen::Vector2d& bearing, const Eigen::Vector2d& axis, double max_step_rad) {
  const double gap = std::atan2(bearing.x() * axis.y() - bearing.y() * axis.x(), bearing.dot(axis));
  return Eigen::Rotation2Dd(std::clamp(gap, -max_step_rad, max_step_rad)) * bearing;
}

}  // namespace kestrel::aim
