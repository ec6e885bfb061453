#include "kestrel/camera_rig/camera_rig.hpp"

#include <cmath>
#include <kestrel/geometry/pinhole.hpp>

namespace kestrel::sensors {

msg::StereoCalibration CameraRigConfig::calibration() const {
  msg::StereoCalibration c;
  c.width = width;
  c.height = height;
  c.fx = c.fy = geometry::focal_from_hfov(width, hfov_deg);
  c.cx = (width - 1) / 2.0;
  c.cy = (height - 1) / 2.0;
  c.baseline_m = baseline_m;
  return c;
}

geometry::CameraPose CameraRigConfig::pose(const msg::VehicleState* vehicle) const {
  if (!vehicle) return geometry::level_camera(camera_position_m, camera_yaw_deg * M_PI / 180.0);
  return geometry::camera_on_body(vehicle->position, vehicle->orientation, camera_offset_m);
}

msg::CameraMount mount_on_vehicle(const std::string& frame, const Eigen::Vector3d& position,
                                  const Eigen::Vector3d& rpy_deg) {
  const Eigen::Vector3d r = rpy_deg * M_PI / 180.0;
  const Eigen::Quaterniond turn = Eigen::AngleAxisd(r.z(), Eigen::Vector3d::UnitZ()) *
                                  Eigen::AngleAxisd(r.y(), Eigen::Vector3d::UnitY()) *
                                  Eigen::AngleAxisd(r.x(), Eigen::Vector3d::UnitX());
  msg::CameraMount m;
  m.parent_frame = frame;
  m.position = position;
  m.orientation = (turn * Eigen::Quaterniond(geometry::body_from_camera())).normalized();
  return m;
}

msg::CameraMount CameraRigConfig::mount(const std::string* vehicle_frame) const {
  msg::CameraMount m;
  if (vehicle_frame) {
    m = mount_on_vehicle(*vehicle_frame, camera_offset_m);
  } else {
    const geometry::CameraPose fixed = pose(nullptr);
    m.position = fixed.position_world;
    m.orientation = Eigen::Quaterniond(fixed.world_from_camera());
  }
  return m;
}

bool CameraRigConfig::in_view(const Eigen::Vector3d& p) const {
  return geometry::in_view(calibration(), min_depth_m, max_depth_m, p);
}

msg::GroundTruth CameraRigConfig::seen(const msg::GroundTruth& truth, Time stamp,
                                       const geometry::CameraPose& camera) const {
  msg::GroundTruth out;
  out.stamp = stamp;
  const double dt = to_seconds(stamp - truth.stamp);
  for (const auto& o : truth.objects) {
    msg::GroundTruthObject now = o;
    now.position_world = o.position_world + o.velocity_world * dt;
    now.position_camera = camera.to_camera(now.position_world);
    now.in_view = in_view(now.position_camera);
    out.objects.push_back(now);
  }
  return out;
}

}  // namespace kestrel::sensors
