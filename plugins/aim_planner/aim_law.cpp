#include "aim_law.hpp"

#include <algorithm>
#include <cmath>
#include <kestrel/geometry/frames.hpp>
#include <limits>

namespace kestrel::aim {

double angle_difference(double a, double b) {
  double d = std::remainder(a - b, 2.0 * M_PI);
  if (d <= -M_PI) d += 2.0 * M_PI;
  return d;
}

AimPose aim_pose(const Eigen::Vector3d& intruder_world, const Eigen::Vector3d& hunter_position, double current_yaw,
                 const Eigen::Vector3d& aim_point_camera, const Eigen::Vector3d& camera_offset_body) {
  AimPose pose;
  const Eigen::Vector3d camera =
      hunter_position + Eigen::AngleAxisd(current_yaw, Eigen::Vector3d::UnitZ()) * camera_offset_body;
  const Eigen::Vector2d towards = (intruder_world - camera).head<2>();
  pose.yaw = towards.norm() > 0.05 ? std::atan2(towards.y(), towards.x()) : current_yaw;
  // A level camera with that heading, placed so that the intruder appears at the aim point.
  const geometry::CameraPose level = geometry::level_camera(Eigen::Vector3d::Zero(), pose.yaw);
  const Eigen::Vector3d camera_wanted = intruder_world - level.world_from_camera() * aim_point_camera;
  pose.position = camera_wanted - level.body_to_world * camera_offset_body;
  return pose;
}

AimReference::AimReference(Limits limits, const Eigen::Vector3d& start, double start_yaw)
    : limits_(limits), position_(start), yaw_(start_yaw) {}

void AimReference::move(const Eigen::Vector3d& wanted_velocity, double dt) {
  Eigen::Vector3d v = wanted_velocity;
  if (v.norm() > limits_.max_speed) v *= limits_.max_speed / v.norm();
  Eigen::Vector3d dv = v - velocity_;
  const double max_dv = limits_.max_acceleration * dt;
  if (dv.norm() > max_dv) dv *= max_dv / dv.norm();
  acceleration_ = dt > 0.0 ? Eigen::Vector3d(dv / dt) : Eigen::Vector3d::Zero();
  position_ += (velocity_ + 0.5 * dv) * dt;  // exact for a constant acceleration over dt
  velocity_ += dv;
}

void AimReference::advance(const AimPose& goal, const Eigen::Vector3d& goal_velocity, double dt) {
  move(goal_velocity + limits_.gain * (goal.position - position_), dt);
  const double turn =
      std::clamp(angle_difference(goal.yaw, yaw_), -limits_.max_yaw_rate * dt, limits_.max_yaw_rate * dt);
  yaw_rate_ = dt > 0.0 ? turn / dt : 0.0;
  yaw_ = angle_difference(yaw_ + turn, 0.0);
}

void AimReference::hold(double dt, double yaw_rate) {
  move(Eigen::Vector3d::Zero(), dt);
  yaw_rate_ = std::clamp(yaw_rate, -limits_.max_yaw_rate, limits_.max_yaw_rate);
  yaw_ = angle_difference(yaw_ + yaw_rate_ * dt, 0.0);
}

double predicted_miss(const net::NetModel& net, const geometry::CameraPose& launcher,
                      const Eigen::Vector3d& launcher_velocity, const TargetMotion& target) {
  const net::NetShot shot = net.fire(0.0, launcher, launcher_velocity);
  const auto& p = net.params();
  // The open window in steps of at most 10 ms: the net moves a few centimetres per step.
  const int steps = std::max(1, static_cast<int>(std::ceil(p.open_for_s / 0.01)));
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= steps; ++i) {
    const double tau = p.flight_time_s + p.open_for_s * i / steps;
    best = std::min(best, (net.position(shot, tau) - target.at(tau)).norm());
  }
  return best;
}

FireTrigger::FireTrigger(double capture_radius_m, double dwell_s, double cooldown_s)
    : radius_(capture_radius_m), dwell_(dwell_s), cooldown_(cooldown_s) {}

bool FireTrigger::update(double t, std::optional<double> miss_m) {
  if (!miss_m || !(*miss_m <= radius_)) {
    within_since_ = -1.0;
    return false;
  }
  if (within_since_ < 0.0) within_since_ = t;
  if (t - within_since_ + 1e-9 < dwell_ || t - last_fire_ + 1e-9 < cooldown_) return false;
  last_fire_ = t;
  within_since_ = -1.0;  // a new shot needs a new dwell
  return true;
}

}  // namespace kestrel::aim
