#pragma once
// A stereo camera as a simulated sensor node declares it: image size, frame rate, field of view,
// baseline, depth range, and where it stands (fixed in the world, or mounted on a vehicle whose
// pose arrives on an input). The rendered camera (sim_stereo) and the detection-level one
// (detection_model) bind this group into their config structs with one call, so a graph can swap
// one for the other by changing the node's type, and both see the world alike.
#include <Eigen/Core>
#include <kestrel/config_spec.hpp>
#include <kestrel/geometry/frames.hpp>
#include <kestrel/messages/ground_truth.hpp>
#include <kestrel/messages/stereo_frame.hpp>
#include <kestrel/messages/vehicle_state.hpp>
#include <string>

namespace kestrel::sensors {

struct CameraRigConfig {
  int width = 640;
  int height = 480;
  double fps = 30.0;
  double hfov_deg = 70.6;
  double baseline_m = 0.12;
  double min_depth_m = 0.5;
  double max_depth_m = 15.0;
  Eigen::Vector3d camera_position_m{0.0, 0.0, 2.0};
  double camera_yaw_deg = 0.0;
  Eigen::Vector3d camera_offset_m{0.1, 0.0, 0.0};

  /// The rectified pinhole calibration: fx = fy from the field of view, principal point centred.
  msg::StereoCalibration calibration() const;
  /// Where the camera is: on the vehicle at `vehicle` (mounted at camera_offset_m), or, without
  /// one, at camera_position_m looking along camera_yaw_deg.
  geometry::CameraPose pose(const msg::VehicleState* vehicle) const;
  /// Where the camera stands for viewers: at camera_offset_m in the body frame `vehicle_frame`
  /// of the vehicle carrying it, or, without one, fixed in the world.
  msg::CameraMount mount(const std::string* vehicle_frame) const;
  /// True when a camera-frame point is within the depth range and images inside the picture.
  bool in_view(const Eigen::Vector3d& p_camera) const;
  /// The intruders of `truth` as this camera sees them at `stamp`: moved to that time with their
  /// velocity, in its frame, with in_view set.
  msg::GroundTruth seen(const msg::GroundTruth& truth, Time stamp, const geometry::CameraPose& camera) const;
};

/// A camera mounted on a vehicle: at `position` (m) in its body frame `frame`, looking along the
/// body's x axis turned by roll, pitch and yaw (`rpy_deg`, about x, y, z in that order).
msg::CameraMount mount_on_vehicle(const std::string& frame, const Eigen::Vector3d& position,
                                  const Eigen::Vector3d& rpy_deg = Eigen::Vector3d::Zero());

/// Declares a real camera's mount (mount_frame, mount_position_m, mount_rpy_deg), as
/// mount_on_vehicle() takes it, bound to the three fields of Config.
template <class Config>
void declare_camera_mount(ConfigSpec<Config>& c, std::string Config::*frame, Eigen::Vector3d Config::*position,
                          Eigen::Vector3d Config::*rpy_deg) {
  c.param("mount_frame", frame).describe("frame carrying the camera (a vehicle's node id, or world), for /tf");
  c.param("mount_position_m", position).with_unit("m").describe("left optical centre in that frame");
  c.param("mount_rpy_deg", rpy_deg)
      .with_unit("deg")
      .describe("turn of the camera from looking along the frame's x: roll, pitch, yaw");
}

/// Declares the CameraRigConfig fields of `group` in c, with the defaults `group` has in a
/// default-constructed Config.
template <class Config>
void declare_camera_rig(ConfigSpec<Config>& c, CameraRigConfig Config::*group) {
  using R = CameraRigConfig;
  c.param("width", group, &R::width).range(64, 4096).with_unit("px").describe("image width");
  c.param("height", group, &R::height).range(48, 4096).with_unit("px").describe("image height");
  c.param("fps", group, &R::fps).range(0.1, 240.0).with_unit("Hz").describe("frame rate");
  c.param("hfov_deg", group, &R::hfov_deg)
      .range(10.0, 150.0)
      .with_unit("deg")
      .describe(
          "horizontal field of view; 70.6 gives the oCamS's rectified fx = 452 px at 640 px (the paper states 92.8)");
  c.param("baseline_m", group, &R::baseline_m).range(0.01, 2.0).with_unit("m").describe("distance between the cameras");
  c.param("min_depth_m", group, &R::min_depth_m).range(0.05, 100.0).with_unit("m").describe("nearest depth seen");
  c.param("max_depth_m", group, &R::max_depth_m).range(0.1, 1000.0).with_unit("m").describe("farthest depth seen");
  c.param("camera_position_m", group, &R::camera_position_m)
      .with_unit("m")
      .describe("fixed camera position (world), when `pose` is not connected");
  c.param("camera_yaw_deg", group, &R::camera_yaw_deg).range(-360.0, 360.0).with_unit("deg").describe("fixed heading");
  c.param("camera_offset_m", group, &R::camera_offset_m)
      .with_unit("m")
      .describe("camera position in the vehicle's body frame, when `pose` is connected");
  c.rule("min_depth_m < max_depth_m", {"min_depth_m", "max_depth_m"},
         [group](const Config& k) { return (k.*group).min_depth_m < (k.*group).max_depth_m; });
}

}  // namespace kestrel::sensors
