#include "kestrel/guidance/aim_reference.hpp"

#include <algorithm>
#include <cmath>
#include <kestrel/vehicle/thrust_limit.hpp>

namespace kestrel::guidance {

AimReference::AimReference(Limits limits, const Eigen::Vector3d& start, double start_yaw)
    : limits_(limits), position_(start), yaw_(start_yaw) {}

void AimReference::move(const Eigen::Vector3d& wanted_velocity, double dt) {
  Eigen::Vector3d v = wanted_velocity;
  if (v.norm() > limits_.max_speed) v *= limits_.max_speed / v.norm();
  Eigen::Vector3d dv = v - velocity_;
  const double max_dv = limits_.max_acceleration * dt;
  if (dv.norm() > max_dv) dv *= max_dv / dv.norm();
  // A climb braked while the hunter speeds up tilts it most: the thrust is then short and leaning.
  if (dt > 0.0 && limits_.max_tilt < M_PI / 2.0)
    dv = vehicle::tilt_limited_acceleration(dv / dt, limits_.max_tilt, kGravity_m_s2) * dt;
  acceleration_ = dt > 0.0 ? Eigen::Vector3d(dv / dt) : Eigen::Vector3d::Zero();
  position_ += (velocity_ + 0.5 * dv) * dt;  // exact for a constant acceleration over dt
  velocity_ += dv;
}

void AimReference::turn_to(double yaw, double dt) {
  const double turn = std::clamp(angle_difference(yaw, yaw_), -limits_.max_yaw_rate * dt, limits_.max_yaw_rate * dt);
  yaw_rate_ = dt > 0.0 ? turn / dt : 0.0;
  yaw_ = angle_difference(yaw_ + turn, 0.0);
}

void AimReference::advance(const AimPose& goal, const Eigen::Vector3d& goal_velocity, double dt) {
  move(goal_velocity + limits_.gain * (goal.position - position_), dt);
  turn_to(goal.yaw, dt);
}

void AimReference::steer(const Eigen::Vector3d& wanted_velocity, double yaw, double dt) {
  move(wanted_velocity, dt);
  turn_to(yaw, dt);
}

void AimReference::hold(double dt, double yaw_rate) {
  move(Eigen::Vector3d::Zero(), dt);
  yaw_rate_ = std::clamp(yaw_rate, -limits_.max_yaw_rate, limits_.max_yaw_rate);
  yaw_ = angle_difference(yaw_ + yaw_rate_ * dt, 0.0);
}

}  // namespace kestrel::guidance
