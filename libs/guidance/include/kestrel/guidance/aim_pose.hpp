#pragma once
// The paper's aim (section 2.4): the net opens best with the intruder at x_E^d = [0, 1, 2] m in
// the camera frame (2 m ahead of the launcher, 1 m below it). The aim pose is where the hunter
// must be, and which way it must face, for a target to sit there.
#include <Eigen/Core>

namespace kestrel::guidance {

/// Where the net opens, and where the camera that sees it sits.
struct AimGeometry {
  Eigen::Vector3d aim_point_camera{0.0, 1.0, 2.0};    ///< x_E^d, camera frame (x right, y down, z forward)
  Eigen::Vector3d camera_offset_body{0.1, 0.0, 0.0};  ///< the camera in the body frame
};

inline constexpr double kGravity_m_s2 = 9.81;

struct AimPose {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< hunter body position (world)
  double yaw = 0.0;                                    ///< hunter heading (world, rad)
};

/// Where the hunter must be, level, for an intruder at `intruder_world` to sit at `aim_point_camera`
/// of its camera (mounted at `camera_offset_body`, looking along body x), heading straight at
/// the intruder from `hunter_position`. Keeps `current_yaw` when the intruder is right above or
/// below.
AimPose aim_pose(const Eigen::Vector3d& intruder_world, const Eigen::Vector3d& hunter_position, double current_yaw,
                 const Eigen::Vector3d& aim_point_camera, const Eigen::Vector3d& camera_offset_body);
inline AimPose aim_pose(const Eigen::Vector3d& intruder_world, const Eigen::Vector3d& hunter_position,
                        double current_yaw, const AimGeometry& geometry) {
  return aim_pose(intruder_world, hunter_position, current_yaw, geometry.aim_point_camera, geometry.camera_offset_body);
}

/// The same for a hunter that will be accelerating at `acceleration` (world, m/s^2) while it
/// holds the aim: a multirotor tilts its thrust, and the camera and launcher with it, along
/// acceleration + gravity (the Lee controller's attitude, vehicle::attitude_along), so the point
/// its net opens at swings with the tilt: at the paper's x_E^d by 2.3 m times a pitch in radians,
/// 1 m times a roll.
/// Zero acceleration gives the level pose above.
AimPose aim_pose(const Eigen::Vector3d& intruder_world, const Eigen::Vector3d& hunter_position, double current_yaw,
                 const AimGeometry& geometry, const Eigen::Vector3d& acceleration, double gravity_m_s2 = kGravity_m_s2);

/// The wrapped difference a - b, in (-pi, pi].
double angle_difference(double a, double b);

}  // namespace kestrel::guidance
