#include "setpoint_guard.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace kestrel::mavlink {

namespace {
constexpr double kGravity = 9.81;
}  // namespace

std::optional<msg::TrajectorySetpoint> SetpointGuard::position(const msg::TrajectorySetpoint& in) {
  if (!in.position.allFinite() || !in.velocity.allFinite() || !in.acceleration.allFinite() || !std::isfinite(in.yaw) ||
      !std::isfinite(in.yaw_rate)) {
    ++counts_.non_finite;
    return std::nullopt;
  }
  msg::TrajectorySetpoint out = in;
  out.position = in.position.cwiseMax(limits_.fence_min).cwiseMin(limits_.fence_max);
  if (out.position != in.position) ++counts_.fence_clamps;
  const double speed = in.velocity.norm();
  if (speed > limits_.max_speed_m_s) {
    out.velocity *= limits_.max_speed_m_s / speed;
    ++counts_.speed_clamps;
  }
  // Tilt: a horizontal acceleration a needs a tilt of atan(a / g) to hold the height.
  const double max_horizontal = kGravity * std::tan(limits_.max_tilt_deg * std::numbers::pi / 180.0);
  const double horizontal = in.acceleration.head<2>().norm();
  if (horizontal > max_horizontal) {
    out.acceleration.head<2>() *= max_horizontal / horizontal;
    ++counts_.tilt_clamps;
  }
  return out;
}

std::optional<msg::AttitudeTarget> SetpointGuard::attitude(const msg::AttitudeTarget& in) {
  if (!in.orientation.coeffs().allFinite() || in.orientation.norm() < 1e-6 || !in.body_rates.allFinite() ||
      !std::isfinite(in.thrust_n) || !std::isfinite(in.hover_thrust_n) || in.hover_thrust_n <= 0.0) {
    ++counts_.non_finite;
    return std::nullopt;
  }
  msg::AttitudeTarget out = in;
  out.orientation.normalize();
  // Tilt: the angle between the body's up axis and the world's. Beyond the limit, rotate the
  // body's up back toward vertical about their common perpendicular, keeping the heading.
  const Eigen::Vector3d up = out.orientation * Eigen::Vector3d::UnitZ();
  const double tilt = std::acos(std::clamp(up.z(), -1.0, 1.0));
  const double limit = limits_.max_tilt_deg * std::numbers::pi / 180.0;
  if (tilt > limit) {
    const Eigen::Vector3d axis = up.cross(Eigen::Vector3d::UnitZ());
    const Eigen::Vector3d turn = axis.norm() > 1e-9 ? axis.normalized() : Eigen::Vector3d::UnitX();
    out.orientation = (Eigen::Quaterniond(Eigen::AngleAxisd(tilt - limit, turn)) * out.orientation).normalized();
    ++counts_.tilt_clamps;
  }
  return out;
}

double SetpointGuard::normalised_thrust(const msg::AttitudeTarget& in, double hover_fraction) {
  const double t = in.thrust_n / in.hover_thrust_n * hover_fraction;
  const double clamped = std::clamp(t, 0.0, 1.0);
  if (clamped != t) ++counts_.thrust_clamps;
  return clamped;
}

}  // namespace kestrel::mavlink
