// The aim law of the paper's section 2.4 and the parts around it: the aim pose, the limited
// reference the controller follows, and the fire decision.
#include <gmock/gmock.h>

#include <cmath>
#include <kestrel/geometry/frames.hpp>
#include <random>

#include "aim_law.hpp"

using namespace kestrel;
using namespace kestrel::aim;

namespace {
const Eigen::Vector3d kAim(0.0, 1.0, 2.0);  // x_E^d: 2 m ahead, 1 m below
const Eigen::Vector3d kOffset(0.1, 0.0, 0.0);
}  // namespace

TEST(AimLaw, HunterTwoMetresBehindAndOneAboveFacingTheIntruder) {
  const AimPose p = aim_pose({5.0, 0.0, 2.0}, {0.0, 0.0, 2.0}, 0.0, kAim, kOffset);
  EXPECT_NEAR(p.yaw, 0.0, 1e-12);
  EXPECT_TRUE(p.position.isApprox(Eigen::Vector3d(2.9, 0.0, 3.0), 1e-12));  // camera at (3, 0, 3)
  const AimPose left = aim_pose({0.0, 5.0, 2.0}, {0.0, 0.0, 2.0}, 0.0, kAim, kOffset);
  EXPECT_NEAR(left.yaw, std::atan2(5.0, -0.1), 1e-12);  // seen from the camera, 0.1 m ahead of the centre
}

TEST(AimLaw, FromTheAimPoseTheIntruderIsAtTheAimPoint) {
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> u(-8.0, 8.0);
  for (int i = 0; i < 200; ++i) {
    // Drawn in sequence, in the order GCC evaluated the old constructor arguments: every compiler agrees.
    const double iz = u(random), iy = u(random), ix = u(random);
    const Eigen::Vector3d intruder(ix, iy, 2.0 + 0.2 * iz);
    const double hy = u(random), hx = u(random);
    const Eigen::Vector3d hunter(hx, hy, 2.0);
    const AimPose p = aim_pose(intruder, hunter, 0.3, kAim, kOffset);
    const auto camera = geometry::camera_on_body(
        p.position, Eigen::Quaterniond(Eigen::AngleAxisd(p.yaw, Eigen::Vector3d::UnitZ())), kOffset);
    EXPECT_LT((camera.to_camera(intruder) - kAim).norm(), 1e-9) << i;
  }
}

TEST(AimLaw, AngleDifferenceWraps) {
  EXPECT_NEAR(angle_difference(M_PI - 0.1, -M_PI + 0.1), -0.2, 1e-12);
  EXPECT_NEAR(angle_difference(-M_PI + 0.1, M_PI - 0.1), 0.2, 1e-12);
  EXPECT_NEAR(angle_difference(0.5, 0.2), 0.3, 1e-12);
  EXPECT_NEAR(angle_difference(M_PI, 0.0), M_PI, 1e-12);
}

TEST(AimReference, ReachesAStillGoalWithinItsLimits) {
  const AimReference::Limits limits{1.0, 2.0, 3.0, 1.0};
  AimReference r(limits, {0, 0, 0}, 0.0);
  AimPose goal;
  goal.position = {10.0, 0.0, 2.0};
  goal.yaw = 3.0;
  const double dt = 0.02;
  Eigen::Vector3d last_v = Eigen::Vector3d::Zero();
  for (int i = 0; i < 1500; ++i) {
    const double last_yaw = r.yaw();
    r.advance(goal, Eigen::Vector3d::Zero(), dt);
    EXPECT_LE(r.velocity().norm(), 2.0 + 1e-9);
    EXPECT_LE((r.velocity() - last_v).norm(), 3.0 * dt + 1e-9);
    EXPECT_LE(std::abs(angle_difference(r.yaw(), last_yaw)), 1.0 * dt + 1e-9);
    last_v = r.velocity();
  }
  EXPECT_LT((r.position() - goal.position).norm(), 0.01);
  EXPECT_NEAR(r.yaw(), 3.0, 1e-9);
}

TEST(AimReference, TurnsTheShortWayAndFollowsAMovingGoal) {
  AimReference r({1.0, 5.0, 5.0, 1.0}, {0, 0, 2}, 170.0 * M_PI / 180.0);
  AimPose goal;
  goal.position = {0, 0, 2};
  goal.yaw = -170.0 * M_PI / 180.0;
  r.advance(goal, Eigen::Vector3d::Zero(), 0.1);
  EXPECT_GT(angle_difference(r.yaw(), 170.0 * M_PI / 180.0), 0.0);  // through 180, not back through 0
  // A goal moving at 1 m/s: the feed-forward removes the lag once settled.
  AimReference f({1.0, 5.0, 5.0, 1.0}, {0, 0, 2}, 0.0);
  for (int i = 0; i < 1000; ++i) {
    goal.position = Eigen::Vector3d(0.02 * i, 0, 2);
    goal.yaw = 0.0;
    f.advance(goal, Eigen::Vector3d(1.0, 0, 0), 0.02);
  }
  EXPECT_LT((f.position() - goal.position).norm(), 0.03);
  EXPECT_NEAR(f.velocity().x(), 1.0, 1e-3);
}

TEST(AimReference, HoldStopsAndSearchTurns) {
  AimReference r({1.0, 5.0, 2.0, 1.0}, {0, 0, 2}, 0.0);
  AimPose goal;
  goal.position = {20, 0, 2};
  for (int i = 0; i < 100; ++i) r.advance(goal, Eigen::Vector3d::Zero(), 0.02);
  const double speed = r.velocity().norm();
  EXPECT_GT(speed, 1.0);
  for (int i = 0; i < 200; ++i) r.hold(0.02, 0.5);
  EXPECT_NEAR(r.velocity().norm(), 0.0, 1e-12);  // stopped at 2 m/s^2 within speed / 2 s
  EXPECT_NEAR(r.yaw_rate(), 0.5, 1e-12);
}

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
