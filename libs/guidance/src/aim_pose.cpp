#include "kestrel/guidance/aim_pose.hpp"

#include <cmath>
#include <kestrel/geometry/frames.hpp>
#include <kestrel/vehicle/so3.hpp>

namespace kestrel::guidance {

double angle_difference(double a, double b) {
  double d = std::remainder(a - b, 2.0 * M_PI);
  if (d <= -M_PI) d += 2.0 * M_PI;
  return d;
}

namespace {

// Where a body with this attitude must be for its camera to see the intruder at the aim point.
Eigen::Vector3d body_holding(const Eigen::Vector3d& intruder_world, const Eigen::Quaterniond& body_to_world,
                             const Eigen::Vector3d& aim_point_camera, const Eigen::Vector3d& camera_offset_body) {
  const geometry::CameraPose camera{Eigen::Vector3d::Zero(), body_to_world};
  const Eigen::Vector3d camera_wanted = intruder_world - camera.world_from_camera() * aim_point_camera;
  return camera_wanted - camera.body_to_world * camera_offset_body;
}

}  // namespace

AimPose aim_pose(const Eigen::Vector3d& intruder_world, const Eigen::Vector3d& hunter_position, double current_yaw,
                 const Eigen::Vector3d& aim_point_camera, const Eigen::Vector3d& camera_offset_body) {
  AimPose pose;
  const Eigen::Vector3d camera =
      hunter_position + Eigen::AngleAxisd(current_yaw, Eigen::Vector3d::UnitZ()) * camera_offset_body;
  const Eigen::Vector2d towards = (intruder_world - camera).head<2>();
  pose.yaw = towards.norm() > 0.05 ? std::atan2(towards.y(), towards.x()) : current_yaw;
  // A level camera with that heading, placed so that the intruder appears at the aim point.
  pose.position = body_holding(intruder_world, geometry::level_camera(Eigen::Vector3d::Zero(), pose.yaw).body_to_world,
                               aim_point_camera, camera_offset_body);
  return pose;
}

AimPose aim_pose(const Eigen::Vector3d& intruder_world, const Eigen::Vector3d& hunter_position, double current_yaw,
                 const AimGeometry& geometry, const Eigen::Vector3d& acceleration, double gravity_m_s2) {
  AimPose pose = aim_pose(intruder_world, hunter_position, current_yaw, geometry);
  const Eigen::Vector3d thrust = acceleration + gravity_m_s2 * Eigen::Vector3d::UnitZ();
  // Level; or a dive faster than gravity, which no attitude holds.
  if (acceleration.isZero() || thrust.z() <= 0.1 * gravity_m_s2) return pose;
  // The heading stays on the intruder; the camera tilts with the thrust.
  pose.position = body_holding(intruder_world, Eigen::Quaterniond(vehicle::attitude_along(thrust, pose.yaw)),
                               geometry.aim_point_camera, geometry.camera_offset_body);
  return pose;
}

}  // namespace kestrel::guidance
