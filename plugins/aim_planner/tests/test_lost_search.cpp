// Where a hunter that lost its target turns to look for it: the side its last estimate, flown on,
// now lies on.
#include <gtest/gtest.h>

#include <cmath>

#include "lost_search.hpp"

using namespace kestrel::aim;

TEST(LostSearch, TurnsToTheSideTheTargetWent) {
  const Eigen::Vector3d hunter(1.0, 2.0, 3.0);
  // Facing +x (east): a target to the north (left) is looked for counter-clockwise, to the south clockwise.
  EXPECT_EQ(search_side(0.0, hunter, hunter + Eigen::Vector3d(2.0, 1.0, 0.0)), 1.0);
  EXPECT_EQ(search_side(0.0, hunter, hunter + Eigen::Vector3d(2.0, -1.0, 0.0)), -1.0);
  // Behind the hunter and to its right: clockwise is the shorter way round.
  EXPECT_EQ(search_side(0.0, hunter, hunter + Eigen::Vector3d(-5.0, -0.5, 0.0)), -1.0);
  // Facing north (90 deg), east is to the right.
  EXPECT_EQ(search_side(M_PI / 2.0, hunter, hunter + Eigen::Vector3d(3.0, 0.2, 0.0)), -1.0);
  EXPECT_EQ(search_side(M_PI / 2.0, hunter, hunter + Eigen::Vector3d(-3.0, 0.2, 0.0)), 1.0);
  // Straight ahead, or height only: counter-clockwise.
  EXPECT_EQ(search_side(0.0, hunter, hunter + Eigen::Vector3d(4.0, 0.0, 0.0)), 1.0);
  EXPECT_EQ(search_side(0.0, hunter, hunter + Eigen::Vector3d(0.0, 0.0, 2.0)), 1.0);
}

TEST(LostSearch, AnEvaderThatPassedBehindIsLookedForWhereItFled) {
  // Last seen 2 m ahead and 0.5 m to the left, fleeing south-west at 6 m/s; 1.5 s later it is
  // behind the hunter, on the right.
  const Eigen::Vector3d hunter(0.0, 0.0, 3.0), last(2.0, 0.5, 3.0);
  const Eigen::Vector3d velocity = 6.0 * Eigen::Vector3d(-1.0, -1.0, 0.0).normalized();
  const Eigen::Vector3d now = expected_position(last, velocity, 1.5);
  EXPECT_NEAR((now - last).norm(), 9.0, 1e-12);
  EXPECT_LT(now.x(), hunter.x());
  EXPECT_EQ(search_side(0.0, hunter, last), 1.0);  // where it was last seen: to the left
  EXPECT_EQ(search_side(0.0, hunter, now), -1.0);  // where it went: to the right
}
