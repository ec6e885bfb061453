// The net's flight: it opens at x_E^d relative to the launch pose, inherits the launcher's
// velocity, and catches only what is within its radius while it is open.
#include <gmock/gmock.h>

#include <kestrel/geometry/frames.hpp>

#include "net_model.hpp"

using namespace kestrel;
using namespace kestrel::net;

TEST(NetModel, OpensTwoMetresAheadAndOneBelowTheLauncher) {
  const NetModel model(NetParams{});
  // A level launcher at 3 m looking along world +y.
  const auto launcher = geometry::level_camera({1.0, 2.0, 3.0}, M_PI / 2);
  const NetShot shot = model.fire(10.0, launcher, Eigen::Vector3d::Zero());
  EXPECT_TRUE(model.position(shot, 10.4).isApprox(Eigen::Vector3d(1.0, 4.0, 2.0), 1e-12));
  EXPECT_TRUE(model.position(shot, 10.0).isApprox(Eigen::Vector3d(1.0, 2.0, 3.0), 1e-12));
  // A parabola: halfway, the drop is less than half (it was thrown upward to arrive 1 m down).
  EXPECT_GT(model.position(shot, 10.2).z(), 2.5);
  EXPECT_FALSE(model.open(shot, 10.3));
  EXPECT_TRUE(model.open(shot, 10.4));
  EXPECT_TRUE(model.open(shot, 10.7));
  EXPECT_FALSE(model.open(shot, 10.71));
  EXPECT_TRUE(model.spent(shot, 10.71));
}

TEST(NetModel, InheritsTheLaunchersVelocity) {
  const NetModel model(NetParams{});
  const auto launcher = geometry::level_camera({0.0, 0.0, 3.0}, 0.0);
  const NetShot shot = model.fire(0.0, launcher, Eigen::Vector3d(2.0, 0.0, 0.0));
  EXPECT_TRUE(model.position(shot, 0.4).isApprox(Eigen::Vector3d(2.0 + 0.8, 0.0, 2.0), 1e-12));
}

TEST(NetModel, CatchesWithinItsRadiusWhileOpen) {
  const NetModel model(NetParams{});
  const auto launcher = geometry::level_camera({0.0, 0.0, 3.0}, 0.0);
  const NetShot shot = model.fire(0.0, launcher, Eigen::Vector3d::Zero());
  const Eigen::Vector3d centre = model.position(shot, 0.4);  // (2, 0, 2)
  EXPECT_TRUE(model.catches(shot, 0.4, centre + Eigen::Vector3d(0.0, 0.59, 0.0)));
  EXPECT_FALSE(model.catches(shot, 0.4, centre + Eigen::Vector3d(0.0, 0.61, 0.0)));
  EXPECT_FALSE(model.catches(shot, 0.2, model.position(shot, 0.2)));  // still folded
}
