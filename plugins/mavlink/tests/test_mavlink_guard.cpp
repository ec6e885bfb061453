// The sink's guard on known cases: what is refused, what is clamped and to what.
#include <gmock/gmock.h>

#include <kestrel/geometry/frames.hpp>
#include <limits>
#include <numbers>

#include "setpoint_guard.hpp"

using namespace kestrel;
using namespace kestrel::mavlink;
using Eigen::Vector3d;
using std::numbers::pi;

TEST(SetpointGuard, RefusesWhatIsNotFiniteAndKeepsWhatIsInside) {
  SetpointGuard guard({});
  msg::TrajectorySetpoint sp;
  sp.position = {1, 2, 3};
  sp.velocity = {1, 0, 0};
  const auto kept = guard.position(sp);
  ASSERT_TRUE(kept);
  EXPECT_EQ(kept->position, sp.position);
  EXPECT_EQ(kept->velocity, sp.velocity);
  sp.yaw = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(guard.position(sp));
  sp.yaw = 0;
  sp.velocity.x() = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(guard.position(sp));
  EXPECT_EQ(guard.counts().non_finite, 2u);
  EXPECT_EQ(guard.counts().fence_clamps, 0u);
}

TEST(SetpointGuard, ClampsToTheFenceAndTheSpeedLimit) {
  GuardLimits limits;
  limits.fence_min = {-10, -10, 1};
  limits.fence_max = {10, 10, 20};
  limits.max_speed_m_s = 5;
  SetpointGuard guard(limits);
  msg::TrajectorySetpoint sp;
  sp.position = {25, -3, 0};
  sp.velocity = {0, 6, 8};  // 10 m/s
  const auto out = guard.position(sp);
  ASSERT_TRUE(out);
  EXPECT_EQ(out->position, Vector3d(10, -3, 1));
  EXPECT_LT((out->velocity - Vector3d(0, 3, 4)).norm(), 1e-12);
  EXPECT_EQ(guard.counts().fence_clamps, 1u);
  EXPECT_EQ(guard.counts().speed_clamps, 1u);
}

TEST(SetpointGuard, TipsAnAttitudeBackToTheTiltLimitKeepingItsHeading) {
  SetpointGuard guard({});  // 35 degrees
  msg::AttitudeTarget a;
  a.hover_thrust_n = 15;
  a.thrust_n = 15;
  a.orientation = Eigen::AngleAxisd(0.5, Vector3d::UnitZ()) * Eigen::AngleAxisd(60 * pi / 180, Vector3d::UnitX());
  const auto out = guard.attitude(a);
  ASSERT_TRUE(out);
  const Vector3d up = out->orientation * Vector3d::UnitZ();
  EXPECT_NEAR(std::acos(up.z()) * 180 / pi, 35.0, 1e-9);
  EXPECT_NEAR(geometry::yaw_of(out->orientation), 0.5, 1e-9);
  EXPECT_EQ(guard.counts().tilt_clamps, 1u);

  a.orientation = Eigen::AngleAxisd(20 * pi / 180, Vector3d::UnitY());
  const auto kept = guard.attitude(a);
  ASSERT_TRUE(kept);
  EXPECT_NEAR(kept->orientation.angularDistance(a.orientation), 0.0, 1e-12);
  EXPECT_EQ(guard.counts().tilt_clamps, 1u);

  a.thrust_n = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(guard.attitude(a));
}

TEST(SetpointGuard, ThrustIsNormalisedByTheHoverThrust) {
  SetpointGuard guard({});
  msg::AttitudeTarget a;
  a.hover_thrust_n = 20;
  a.thrust_n = 20;
  EXPECT_DOUBLE_EQ(guard.normalised_thrust(a, 0.45), 0.45);
  a.thrust_n = 10;
  EXPECT_DOUBLE_EQ(guard.normalised_thrust(a, 0.45), 0.225);
  a.thrust_n = 100;
  EXPECT_DOUBLE_EQ(guard.normalised_thrust(a, 0.45), 1.0);
  a.thrust_n = -5;
  EXPECT_DOUBLE_EQ(guard.normalised_thrust(a, 0.45), 0.0);
  EXPECT_EQ(guard.counts().thrust_clamps, 2u);
}

// A 35 degree tilt holds the height with at most g tan(35 deg) = 6.87 m/s^2 sideways; the
// vertical part and the direction are kept.
TEST(SetpointGuard, CutsAHorizontalAccelerationToWhatTheTiltLimitAllows) {
  GuardLimits limits;
  limits.max_tilt_deg = 35;
  SetpointGuard guard(limits);
  msg::TrajectorySetpoint sp;
  sp.position = {0, 0, 5};
  sp.acceleration = {3, 4, 1};  // 5 m/s^2 sideways: allowed
  EXPECT_EQ(guard.position(sp)->acceleration, sp.acceleration);
  sp.acceleration = {6, 8, 1};  // 10 m/s^2 sideways
  const auto cut = guard.position(sp);
  ASSERT_TRUE(cut);
  const double allowed = 9.81 * std::tan(35 * pi / 180);
  EXPECT_NEAR(cut->acceleration.head<2>().norm(), allowed, 1e-9);
  EXPECT_NEAR(cut->acceleration.x() / cut->acceleration.y(), 0.75, 1e-12);
  EXPECT_EQ(cut->acceleration.z(), 1.0);
  EXPECT_EQ(guard.counts().tilt_clamps, 1u);
}
