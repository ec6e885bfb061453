// The fire decision: the predicted miss on the net's ballistics, and the trigger.
#include <gmock/gmock.h>

#include <cmath>
#include <kestrel/geometry/frames.hpp>
#include <random>

#include "fire_decision.hpp"

using namespace kestrel;
using namespace kestrel::aim;

TEST(FireTrigger, FiresAfterTheDwellAndNotAgainWithinTheCooldown) {
  FireTrigger fire(0.5, 0.5, 3.0);
  const double good = 0.22, bad = 0.6;
  EXPECT_FALSE(fire.update(0.0, good));
  EXPECT_FALSE(fire.update(0.3, good));
  EXPECT_FALSE(fire.update(0.4, bad));  // left the radius: the dwell starts again
  EXPECT_FALSE(fire.update(0.5, good));
  EXPECT_FALSE(fire.update(0.9, good));
  EXPECT_TRUE(fire.update(1.0, good));  // 0.5 s within
  EXPECT_FALSE(fire.update(1.6, good));
  EXPECT_FALSE(fire.update(3.9, good));  // within the cooldown
  EXPECT_TRUE(fire.update(4.0, good));
  EXPECT_FALSE(fire.update(10.0, std::nullopt));  // no target, no shot
}

TEST(FireTrigger, ATighterRadiusWaitsForABetterShot) {
  FireTrigger fire(0.5, 0.0, 0.0);
  EXPECT_FALSE(fire.update(0.0, 0.4, 0.3));  // good enough for a spare net, not for the last
  EXPECT_TRUE(fire.update(0.1, 0.25, 0.3));
  EXPECT_TRUE(fire.update(0.2, 0.4));  // the default radius
}

TEST(FireTrigger, WithoutADwellItFiresTheMomentTheMissIsWithinTheRadius) {
  FireTrigger fire(0.5, 0.0, 3.0);
  EXPECT_FALSE(fire.update(0.0, 0.51));
  EXPECT_TRUE(fire.update(0.033, 0.49));
  EXPECT_FALSE(fire.update(0.066, 0.1));                                     // cooldown
  EXPECT_FALSE(fire.update(5.0, std::numeric_limits<double>::quiet_NaN()));  // a NaN miss never fires
}

// The net of the paper's launcher: opens 0.4 s after the shot at x_E^d = [0, 1, 2] m (camera
// frame), stays open 0.3 s flying on. A level launcher at the origin looking along world +x.
TEST(PredictedMiss, IsTheLeastDistanceToTheNetWhileItIsOpen) {
  const net::NetModel net({Eigen::Vector3d(0.0, 1.0, 2.0), 0.4, 0.6, 0.3, 9.81});
  const auto launcher = geometry::level_camera(Eigen::Vector3d::Zero(), 0.0);
  const Eigen::Vector3d zero = Eigen::Vector3d::Zero();  // spelled out: Eigen leaves {} uninitialised
  // The opening point in the world: 2 m ahead, 1 m below.
  const Eigen::Vector3d open(2.0, 0.0, -1.0);
  EXPECT_NEAR(predicted_miss(net, launcher, Eigen::Vector3d::Zero(), {open, zero, zero}), 0.0, 1e-9);
  // A target hovering 0.3 m to the side of it: the net passes it at 0.3 m.
  EXPECT_NEAR(predicted_miss(net, launcher, Eigen::Vector3d::Zero(), {open + Eigen::Vector3d(0, 0.3, 0), zero, zero}),
              0.3, 1e-9);
  // A target crossing at 2 m/s that reaches the opening point at the opening: a hit, though it
  // is 0.8 m to the side when the shot leaves.
  const TargetMotion crossing{open - Eigen::Vector3d(0.0, 0.8, 0.0), Eigen::Vector3d(0.0, 2.0, 0.0), zero};
  EXPECT_NEAR(predicted_miss(net, launcher, Eigen::Vector3d::Zero(), crossing), 0.0, 1e-9);
  // The net flies on after opening: a target where the net will be 0.15 s later is met there;
  // one where it would be after it closed is not.
  const net::NetShot shot = net.fire(0.0, launcher, Eigen::Vector3d::Zero());
  EXPECT_NEAR(predicted_miss(net, launcher, Eigen::Vector3d::Zero(), {net.position(shot, 0.55), zero, zero}), 0.0,
              1e-9);
  EXPECT_GT(predicted_miss(net, launcher, Eigen::Vector3d::Zero(), {net.position(shot, 0.9), zero, zero}), 0.6);
  // The launcher's own velocity carries the net: flying at 1 m/s sideways, the net meets a target
  // that drifts with it, and passes a hovering one 0.4 m to its side.
  const Eigen::Vector3d side(0.0, 1.0, 0.0);
  EXPECT_NEAR(predicted_miss(net, launcher, side, {open, side, zero}), 0.0, 1e-9);
  EXPECT_NEAR(predicted_miss(net, launcher, side, {open, zero, zero}), 0.4, 1e-9);
}
