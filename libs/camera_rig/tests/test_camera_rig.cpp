// The camera's mount, as recordings and the live view publish it on /tf, places the camera where
// the rig renders from: the vehicle's world pose composed with the mount is the camera's pose.
#include <gtest/gtest.h>

#include "kestrel/camera_rig/camera_rig.hpp"

using namespace kestrel;

TEST(CameraRig, TheMountOnTheVehicleComposesWithItsPoseIntoTheCameraPose) {
  sensors::CameraRigConfig rig;
  rig.camera_offset_m = {0.15, -0.02, 0.05};
  msg::VehicleState hunter;
  hunter.position = {3.0, -1.0, 2.5};
  hunter.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()) *
                                          Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitY()));
  const geometry::CameraPose camera = rig.pose(&hunter);
  const std::string hunter_frame = "hunter";
  const msg::CameraMount mount = rig.mount(&hunter_frame);
  EXPECT_EQ(mount.parent_frame, "hunter");
  // world -> hunter (odometry's /tf) then hunter -> camera (the mount's /tf)
  const Eigen::Vector3d position = hunter.position + hunter.orientation * mount.position;
  const Eigen::Matrix3d rotation = (hunter.orientation * mount.orientation).toRotationMatrix();
  EXPECT_TRUE(position.isApprox(camera.position_world, 1e-12));
  EXPECT_TRUE(rotation.isApprox(camera.world_from_camera(), 1e-12));
  // A point ahead of the camera stays ahead of the vehicle.
  EXPECT_GT((mount.orientation * Eigen::Vector3d(0, 0, 5)).x(), 4.9);
}

TEST(CameraRig, AFixedCameraIsMountedInTheWorld) {
  sensors::CameraRigConfig rig;
  rig.camera_position_m = {1.0, 2.0, 2.0};
  rig.camera_yaw_deg = 30.0;
  const geometry::CameraPose camera = rig.pose(nullptr);
  const msg::CameraMount mount = rig.mount(nullptr);
  EXPECT_EQ(mount.parent_frame, "world");
  EXPECT_TRUE(mount.position.isApprox(camera.position_world, 1e-12));
  EXPECT_TRUE(mount.orientation.toRotationMatrix().isApprox(camera.world_from_camera(), 1e-12));
}

TEST(CameraRig, AMountTurnedByPitchLooksDown) {
  // FLU body: a positive pitch about y turns x towards -z, so the optical axis looks 30 deg down.
  const msg::CameraMount m = sensors::mount_on_vehicle("hunter", {0.1, 0, -0.05}, {0, 30, 0});
  const Eigen::Vector3d axis = m.orientation * Eigen::Vector3d::UnitZ();
  EXPECT_TRUE(axis.isApprox(Eigen::Vector3d(std::cos(M_PI / 6), 0, -std::sin(M_PI / 6)), 1e-12));
  // The image's x (right) stays the body's -y: no roll.
  EXPECT_TRUE((m.orientation * Eigen::Vector3d::UnitX()).isApprox(-Eigen::Vector3d::UnitY(), 1e-12));
  EXPECT_EQ(m.parent_frame, "hunter");
}
