// The net's flight: it opens at x_E^d relative to the launch pose, inherits the launcher's
// velocity, and catches only what is within its radius while it is open.
#include <gmock/gmock.h>

#include <cmath>
#include <kestrel/geometry/frames.hpp>
#include <limits>

#include "kestrel/net/net_model.hpp"

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

// The open net flies at about 7 m/s: between two 30 Hz samples of the intruder it moves 0.25 m.
// The sweep checks in between.
TEST(NetModel, ASweepCatchesWhatTheNetCrossesBetweenTwoSamples) {
  const NetModel model(NetParams{});
  const auto launcher = geometry::level_camera({0.0, 0.0, 3.0}, 0.0);
  const NetShot shot = model.fire(0.0, launcher, Eigen::Vector3d::Zero());
  // A hovering intruder 0.595 m to the side of where the net is at t = 0.5 s: within its radius
  // then, but not at the samples 1/60 s either side, when the net is 0.12 m further along.
  const Eigen::Vector3d net_then = model.position(shot, 0.5);
  const Eigen::Vector3d intruder = net_then + Eigen::Vector3d(0.0, 0.595, 0.0);
  const double before = 0.5 - 1.0 / 60.0, after = 0.5 + 1.0 / 60.0;
  ASSERT_FALSE(model.catches(shot, before, intruder));
  ASSERT_FALSE(model.catches(shot, after, intruder));
  double closest = std::numeric_limits<double>::infinity();
  const auto caught = model.sweep(shot, before, intruder, after, intruder, closest);
  ASSERT_TRUE(caught.has_value());
  EXPECT_GT(*caught, before);
  EXPECT_LT(*caught, after);
  EXPECT_LE(closest, 0.6);
  // 0.7 m off: never within the radius; the closest approach is 0.7 m, to the sweep's step.
  closest = std::numeric_limits<double>::infinity();
  const Eigen::Vector3d far = net_then + Eigen::Vector3d(0.0, 0.7, 0.0);
  EXPECT_FALSE(model.sweep(shot, before, far, after, far, closest).has_value());
  EXPECT_NEAR(closest, 0.7, 0.005);
  // Before it opens nothing is caught, even on the net's own path.
  closest = std::numeric_limits<double>::infinity();
  const Eigen::Vector3d early = model.position(shot, 0.2);
  EXPECT_FALSE(model.sweep(shot, 0.18, early, 0.22, early, closest).has_value());
  EXPECT_TRUE(std::isinf(closest));
}
