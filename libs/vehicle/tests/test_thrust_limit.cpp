// The thrust a multirotor can point: never down, never tilted past its limit, height first.
#include <gtest/gtest.h>

#include <cmath>
#include <kestrel/vehicle/thrust_limit.hpp>

using kestrel::vehicle::limit_thrust;

TEST(ThrustLimit, AThrustWithinTheLimitsIsUnchanged) {
  const Eigen::Vector3d thrust(3.0, -4.0, 9.81);  // 27 degrees from vertical
  const auto out = limit_thrust(thrust, 1.0, M_PI / 3.0);
  EXPECT_EQ(out.thrust, thrust);
  EXPECT_FALSE(out.raised);
  EXPECT_FALSE(out.tilted);
}

TEST(ThrustLimit, TooMuchTiltShortensTheHorizontalPartAndKeepsTheHeight) {
  // 20 m/s^2 sideways at 1 g up is 64 degrees; at 45 degrees the horizontal part equals the vertical.
  const auto out = limit_thrust({12.0, 16.0, 9.81}, 1.0, M_PI / 4.0);
  EXPECT_TRUE(out.tilted);
  EXPECT_DOUBLE_EQ(out.thrust.z(), 9.81);
  EXPECT_NEAR(out.thrust.head<2>().norm(), 9.81, 1e-12);
  EXPECT_NEAR(out.thrust.y() / out.thrust.x(), 16.0 / 12.0, 1e-12);  // the direction is kept
}

TEST(ThrustLimit, AThrustPointingDownIsRaisedToTheMinimumThenTilted) {
  const auto out = limit_thrust({2.0, 0.0, -5.0}, 1.0, M_PI / 3.0);
  EXPECT_TRUE(out.raised);
  EXPECT_TRUE(out.tilted);
  EXPECT_DOUBLE_EQ(out.thrust.z(), 1.0);
  EXPECT_NEAR(out.thrust.x(), std::tan(M_PI / 3.0), 1e-12);
}
