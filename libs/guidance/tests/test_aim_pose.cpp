// The aim of the paper's section 2.4: the aim pose, and the limited reference the controller
// follows.
#include <gmock/gmock.h>

#include <cmath>
#include <kestrel/geometry/frames.hpp>
#include <kestrel/guidance/aim_pose.hpp>
#include <kestrel/guidance/aim_reference.hpp>
#include <kestrel/vehicle/so3.hpp>
#include <random>

using namespace kestrel;
using namespace kestrel::guidance;

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

TEST(AimLaw, AHunterAcceleratingForwardPitchesDownAndSitsHigher) {
  // Straight ahead of the camera (no offset): accelerating forward at g, the hunter pitches its
  // nose 45 degrees down, so it holds the intruder 2 m along that axis: sqrt(2) behind and above.
  const AimGeometry ahead{{0.0, 0.0, 2.0}, Eigen::Vector3d::Zero()};
  const AimPose p = aim_pose({5.0, 0.0, 2.0}, {0.0, 0.0, 2.0}, 0.0, ahead, {9.81, 0.0, 0.0});
  EXPECT_NEAR(p.yaw, 0.0, 1e-12);
  EXPECT_TRUE(p.position.isApprox(Eigen::Vector3d(5.0 - std::sqrt(2.0), 0.0, 2.0 + std::sqrt(2.0)), 1e-12));
  // No acceleration is the level pose, bit for bit (the paper graphs keep their figures).
  const AimPose level = aim_pose({5.0, 0.0, 2.0}, {0.0, 0.0, 2.0}, 0.0, kAim, kOffset);
  const AimPose zero = aim_pose({5.0, 0.0, 2.0}, {0.0, 0.0, 2.0}, 0.0, AimGeometry{kAim, kOffset}, {0.0, 0.0, 0.0});
  EXPECT_EQ(zero.position, level.position);
  EXPECT_EQ(zero.yaw, level.yaw);
}

TEST(AimLaw, FromTheTiltedAimPoseTheIntruderIsAtTheAimPoint) {
  // Whatever the acceleration, the camera tilted as the Lee controller tilts the hunter for it
  // sees the intruder at x_E^d.
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> u(-8.0, 8.0);
  for (int i = 0; i < 200; ++i) {
    const double ix = u(random), iy = u(random), iz = u(random);
    const Eigen::Vector3d intruder(ix, iy, 2.0 + 0.2 * iz);
    const double ax = u(random), ay = u(random), az = u(random);
    const Eigen::Vector3d acceleration(ax, ay, 0.5 * az);
    const AimPose p = aim_pose(intruder, {0.0, 0.0, 2.0}, 0.3, AimGeometry{kAim, kOffset}, acceleration);
    const Eigen::Matrix3d attitude = vehicle::attitude_along(acceleration + 9.81 * Eigen::Vector3d::UnitZ(), p.yaw);
    const auto camera = geometry::camera_on_body(p.position, Eigen::Quaterniond(attitude), kOffset);
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

TEST(AimReference, ABrakedClimbWhileSpeedingUpTiltsNoFurtherThanTheLimit) {
  // Climbing at 5 m/s towards a goal ahead and level: the climb is braked while the hunter speeds
  // up, 8 m/s^2 in all. Unlimited, the thrust then leans about 50 degrees; limited to 40, the
  // horizontal part gives way and the braking keeps its share.
  auto largest_tilt = [](double max_tilt) {
    AimReference r({1.0, 12.0, 8.0, 1.0, max_tilt}, {0, 0, 2}, 0.0);
    r.steer({0.0, 0.0, 5.0}, 0.0, 1.0);  // at 5 m/s up, within the 8 m/s^2
    AimPose goal;
    goal.position = {30.0, 0.0, 2.0};
    double tilt = 0.0, first_brake = 0.0;
    for (int i = 0; i < 100; ++i) {
      r.advance(goal, Eigen::Vector3d::Zero(), 0.02);
      const Eigen::Vector3d thrust = r.acceleration() + Eigen::Vector3d(0.0, 0.0, kGravity_m_s2);
      tilt = std::max(tilt, std::atan2(thrust.head<2>().norm(), thrust.z()));
      if (i == 0) first_brake = r.acceleration().z();
    }
    return std::pair{tilt, first_brake};
  };
  const auto [free_tilt, free_brake] = largest_tilt(M_PI / 2.0);
  const auto [tilt, brake] = largest_tilt(40.0 * M_PI / 180.0);
  EXPECT_GT(free_tilt, 45.0 * M_PI / 180.0);
  EXPECT_NEAR(tilt, 40.0 * M_PI / 180.0, 1e-9);
  EXPECT_DOUBLE_EQ(brake, free_brake);  // the vertical part is not shortened
}
