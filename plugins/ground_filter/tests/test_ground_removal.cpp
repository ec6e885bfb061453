// The ground test on points whose answer is known: a camera 2 m above the ground (fx b = 36.48
// px m, the paper's camera at 640x480), level or pitched down, sees the ground, points on its rays
// a fraction of a pixel nearer, points beneath it, and an intruder in the air.
#include <gmock/gmock.h>

#include "ground_removal.hpp"

using namespace kestrel;

namespace {

constexpr double kFocalBaseline = 36.48;

// Level camera 2 m up looking along world +x.
geometry::CameraPose level() { return geometry::level_camera({0.0, 0.0, 2.0}, 0.0); }

// Camera on a body pitched nose down by `deg` (positive about world +y tips +x towards -z).
geometry::CameraPose pitched(double deg) {
  return geometry::CameraPose{{0.0, 0.0, 2.0},
                              Eigen::Quaterniond(Eigen::AngleAxisd(deg * M_PI / 180.0, Eigen::Vector3d::UnitY()))};
}

// The point on the ray through `p` (camera frame) whose disparity is `delta_px` larger.
Eigen::Vector3d nearer_by(const Eigen::Vector3d& p, double delta_px) {
  const double d = kFocalBaseline / p.z();
  return p * (d / (d + delta_px));
}

bool on_ground(const geometry::CameraPose& camera, const Eigen::Vector3d& world) {
  return ground::is_ground(camera.to_camera(world), camera, kFocalBaseline, {});
}

}  // namespace

TEST(GroundRemoval, TheGroundAndWhatLiesBeneathItAreGroundAtEveryRange) {
  for (const auto& camera : {level(), pitched(20.0)}) {
    for (double x : {3.0, 8.0, 15.0, 30.0}) {
      EXPECT_TRUE(on_ground(camera, {x, 0.5, 0.0})) << "on the ground at " << x << " m";
      EXPECT_TRUE(on_ground(camera, {x, -1.0, -0.3})) << "beneath it at " << x << " m";
    }
  }
}

TEST(GroundRemoval, TheMarginIsInDisparityWhateverTheRange) {
  const auto camera = level();
  for (double x : {3.0, 8.0, 15.0}) {
    const Eigen::Vector3d on_ground = camera.to_camera({x, 0.0, 0.0});
    // A quarter pixel nearer: matching's noise, still ground, though at 15 m it floats 0.2 m up.
    const Eigen::Vector3d noisy = nearer_by(on_ground, 0.25);
    EXPECT_TRUE(ground::is_ground(noisy, camera, kFocalBaseline, {})) << x << " m";
    // Three quarters of a pixel nearer: it stands in front of the ground (margin 0.5 px).
    EXPECT_FALSE(ground::is_ground(nearer_by(on_ground, 0.75), camera, kFocalBaseline, {})) << x << " m";
  }
  const Eigen::Vector3d floating = camera.to_world(nearer_by(camera.to_camera({15.0, 0.0, 0.0}), 0.25));
  EXPECT_GT(floating.z(), 0.15);  // a height test at 0.1 m would keep it
}

TEST(GroundRemoval, AnIntruderInTheAirIsNotGroundWhetherTheCameraIsLevelOrPitched) {
  for (const auto& camera : {level(), pitched(20.0)}) {
    for (double x : {2.0, 5.0, 10.0, 15.0}) {
      EXPECT_FALSE(on_ground(camera, {x, 0.0, 2.0})) << "at the camera's height, " << x << " m";  // level ray
      EXPECT_FALSE(on_ground(camera, {x, 1.0, 3.5})) << "above it, " << x << " m";                // rising ray
      EXPECT_FALSE(on_ground(camera, {x, 0.0, 1.0})) << "a metre up, " << x << " m";  // ray meets ground 2x out
    }
  }
  // Below the camera and low over the ground: still not ground while it stands a margin in front.
  EXPECT_FALSE(on_ground(level(), {10.0, 0.0, 0.6}));  // ray meets the ground at 14.3 m: 1.1 px nearer
}

TEST(GroundRemoval, ACloudKeepsItsOtherPointsInOrder) {
  const auto camera = level();
  pcl::PointCloud<pcl::PointXYZ> cloud;
  const auto add = [&](const Eigen::Vector3d& world) {
    const Eigen::Vector3d c = camera.to_camera(world);
    cloud.push_back(pcl::PointXYZ(static_cast<float>(c.x()), static_cast<float>(c.y()), static_cast<float>(c.z())));
  };
  add({5.0, 0.0, 2.2});    // intruder
  add({6.0, 1.0, 0.0});    // ground
  add({9.0, -1.0, 1.5});   // intruder
  add({12.0, 0.0, -0.5});  // beneath the ground
  const auto kept = ground::remove_ground(cloud, camera, kFocalBaseline, {});
  ASSERT_EQ(kept->size(), 2u);
  EXPECT_FLOAT_EQ(kept->points[0].z, cloud.points[0].z);
  EXPECT_FLOAT_EQ(kept->points[1].z, cloud.points[2].z);
  EXPECT_EQ(kept->width, 2u);
}

TEST(GroundRemoval, ACameraBeneathThePlaneOrAPointBehindItIsNeverGround) {
  geometry::CameraPose below = level();
  below.position_world.z() = -1.0;
  EXPECT_FALSE(ground::is_ground({0.0, 1.0, 5.0}, below, kFocalBaseline, {}));
  EXPECT_FALSE(ground::is_ground({0.0, 1.0, -5.0}, level(), kFocalBaseline, {}));
}
