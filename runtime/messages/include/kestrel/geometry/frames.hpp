#pragma once
// The coordinate frames every kestrel plugin agrees on.
//
//   world   W: level and z up, gravity -z. Against a compass it is ENU (x east, y north, as
//              ROS REP 103); ned_enu.hpp converts to the NED of PX4, ArduPilot and MAVLink.
//   body    B: the hunter's body, x forward, y left, z up (FLU), at its centre of mass.
//   camera  C: the optical frame of the left camera: x right, y down, z forward (along the
//              optical axis), as in the paper's equation (1). Mounted on the body looking
//              forward; `camera_offset_body` is its position in B.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>

namespace kestrel::geometry {

/// Rotation taking camera-frame vectors to body-frame vectors: optical z -> body x,
/// optical x -> body -y, optical y -> body -z.
inline Eigen::Matrix3d body_from_camera() {
  Eigen::Matrix3d r;
  r << 0, 0, 1,  //
      -1, 0, 0,  //
      0, -1, 0;
  return r;
}

/// A camera's pose in the world: where its optical centre is and how the body carrying it is
/// oriented.
struct CameraPose {
  Eigen::Vector3d position_world = Eigen::Vector3d::Zero();
  Eigen::Quaterniond body_to_world = Eigen::Quaterniond::Identity();

  Eigen::Matrix3d world_from_camera() const { return body_to_world.toRotationMatrix() * body_from_camera(); }

  Eigen::Vector3d to_camera(const Eigen::Vector3d& p_world) const {
    return world_from_camera().transpose() * (p_world - position_world);
  }
  Eigen::Vector3d to_world(const Eigen::Vector3d& p_camera) const {
    return position_world + world_from_camera() * p_camera;
  }
};

/// Heading of a body (world yaw of its x axis, counter-clockwise from world +x seen from above),
/// whatever its tilt.
inline double yaw_of(const Eigen::Quaterniond& body_to_world) {
  const Eigen::Vector3d forward = body_to_world * Eigen::Vector3d::UnitX();
  return std::atan2(forward.y(), forward.x());
}

/// A level camera at `position` whose optical axis points along world yaw `yaw_rad`
/// (0 = world +x, counter-clockwise seen from above).
inline CameraPose level_camera(const Eigen::Vector3d& position, double yaw_rad) {
  return CameraPose{position, Eigen::Quaterniond(Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()))};
}

/// Camera pose of a camera mounted at `offset_body` on a body with the given world pose.
inline CameraPose camera_on_body(const Eigen::Vector3d& body_position, const Eigen::Quaterniond& body_to_world,
                                 const Eigen::Vector3d& offset_body) {
  return CameraPose{body_position + body_to_world * offset_body, body_to_world};
}

}  // namespace kestrel::geometry
