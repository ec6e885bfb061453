// The searches for a lost target: hold, turn, and back off.
#include <gmock/gmock.h>

#include <cmath>

#include "search.hpp"

using namespace kestrel::aim;

namespace {
// Lost 4 m ahead (+x) of a hunter at the origin facing +x, 3 m up, flying on to the left (+y).
LostTarget lost_ahead() { return LostTarget{{4.0, 0.0, 3.0}, {0.0, 2.0, 0.0}, 1.0, {0.0, 0.0, 2.0}, 0.0, 0.5}; }
}  // namespace

TEST(Search, HoldHoldsPositionAndHeading) {
  HoldSearch hold;
  hold.begin(lost_ahead());
  const SearchStep step = hold.step(3.0, std::nullopt);
  EXPECT_FALSE(step.goal);
  EXPECT_EQ(step.yaw_rate_rad_s, 0.0);
}

TEST(Search, TurnTurnsToTheSideTheTargetWent) {
  TurnSearch turn{TurnSearchConfig{30.0}};
  turn.begin(lost_ahead());
  EXPECT_NEAR(turn.step(0.0, std::nullopt).yaw_rate_rad_s, 30.0 * M_PI / 180.0, 1e-12);  // left: counter-clockwise
  LostTarget right = lost_ahead();
  right.last_velocity.y() = -2.0;
  turn.begin(right);
  EXPECT_NEAR(turn.step(0.0, std::nullopt).yaw_rate_rad_s, -30.0 * M_PI / 180.0, 1e-12);
}

TEST(Search, BackOffStandsBackFacingWhereTheTargetWasThenTurns) {
  BackOffSearch back_off{BackOffConfig{5.0, 0.5, 2.0, 40.0}};
  back_off.begin(lost_ahead());
  const SearchStep early = back_off.step(1.0, std::nullopt);
  ASSERT_TRUE(early.goal);
  // 5 m back from where it was seen, along the line to the hunter (-x), 0.5 m above it, facing +x.
  EXPECT_TRUE(early.goal->position.isApprox(Eigen::Vector3d(-1.0, 0.0, 3.5), 1e-12));
  EXPECT_NEAR(early.goal->yaw, 0.0, 1e-12);
  const SearchStep late = back_off.step(2.5, std::nullopt);
  EXPECT_FALSE(late.goal);
  EXPECT_NEAR(late.yaw_rate_rad_s, 40.0 * M_PI / 180.0, 1e-12);
  // The aim's own time to turn, when it has one, comes first; < 0 holds the standoff.
  EXPECT_FALSE(back_off.step(1.0, 0.5).goal);
  EXPECT_TRUE(back_off.step(10.0, -1.0).goal);
}

TEST(Search, BackOffNeverGoesBelowTheLeastAltitude) {
  BackOffSearch back_off{BackOffConfig{5.0, -4.0, -1.0, 20.0}};
  back_off.begin(lost_ahead());
  EXPECT_DOUBLE_EQ(back_off.step(100.0, std::nullopt).goal->position.z(), 0.5);
}

TEST(Search, TurnsToTheSideTheTargetWent) {
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

TEST(Search, AnEvaderThatPassedBehindIsLookedForWhereItFled) {
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
