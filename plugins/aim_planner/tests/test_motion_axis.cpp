// Where round the target the hunter stands: the target's axis of motion, and the step round the
// standoff circle towards it.
#include <gtest/gtest.h>

#include <cmath>

#include "motion_axis.hpp"

using namespace kestrel::aim;

namespace {
constexpr double kFrame = 1.0 / 30.0;

// A target that flies back and forth along `direction` (a line at 4 m/s, reversing every 2 s),
// with a little motion across it, for `seconds`.
void fly_back_and_forth(MotionAxis& axis, const Eigen::Vector2d& direction, double seconds) {
  const Eigen::Vector2d across(-direction.y(), direction.x());
  for (double t = 0.0; t < seconds; t += kFrame) {
    const double along = 4.0 * std::sin(M_PI * t / 2.0);
    const Eigen::Vector2d v = along * direction + 0.5 * std::cos(3.0 * t) * across;
    axis.update(Eigen::Vector3d(v.x(), v.y(), 0.3), kFrame);
  }
}
}  // namespace

TEST(MotionAxis, IsTheDirectionATargetFliesBackAndForthAlong) {
  MotionAxis axis(2.0);
  const Eigen::Vector2d line = Eigen::Vector2d(1.0, 2.0).normalized();
  fly_back_and_forth(axis, line, 8.0);
  // Signed to the hunter's side: a hunter looking along +line, or along -line, keeps its side.
  const auto ahead = axis.axis(Eigen::Vector2d(1.0, 0.0));
  ASSERT_TRUE(ahead);
  EXPECT_NEAR(std::abs(ahead->dot(line)), 1.0, 0.02);
  EXPECT_GT(ahead->dot(line), 0.0);
  const auto behind = axis.axis(-line);
  ASSERT_TRUE(behind);
  EXPECT_NEAR(behind->dot(line), -1.0, 0.02);
}

TEST(MotionAxis, AHoveringOrCirclingTargetHasNone) {
  MotionAxis hovering(2.0);
  for (int i = 0; i < 300; ++i) hovering.update(Eigen::Vector3d(0.2, -0.1, 0.5), kFrame);
  EXPECT_FALSE(hovering.axis(Eigen::Vector2d(1.0, 0.0)));  // slower than 1 m/s

  MotionAxis circling(2.0);
  for (double t = 0.0; t < 12.0; t += kFrame)
    circling.update(Eigen::Vector3d(5.0 * std::cos(t), 5.0 * std::sin(t), 0.0), kFrame);
  EXPECT_FALSE(circling.axis(Eigen::Vector2d(1.0, 0.0)));         // as fast one way as the other
  EXPECT_FALSE(MotionAxis(2.0).axis(Eigen::Vector2d(1.0, 0.0)));  // nothing seen yet
}

TEST(MotionAxis, FollowsANewAxisOverItsTimeConstant) {
  MotionAxis axis(1.0);
  fly_back_and_forth(axis, Eigen::Vector2d(1.0, 0.0), 6.0);
  fly_back_and_forth(axis, Eigen::Vector2d(0.0, 1.0), 0.2);
  EXPECT_NEAR(std::abs(axis.axis(Eigen::Vector2d(1.0, 0.0))->x()), 1.0, 0.05);  // not yet
  fly_back_and_forth(axis, Eigen::Vector2d(0.0, 1.0), 6.0);
  EXPECT_NEAR(std::abs(axis.axis(Eigen::Vector2d(0.0, 1.0))->y()), 1.0, 0.05);
  axis.reset();
  EXPECT_FALSE(axis.axis(Eigen::Vector2d(0.0, 1.0)));
}

TEST(ApproachDirection, TurnsTheLineOfSightTowardsTheAxisAStepAtATime) {
  const double step = 30.0 * M_PI / 180.0;
  // 90 degrees apart: one step of 30 towards the axis, on the shorter way round.
  const Eigen::Vector2d first = approach_direction(Eigen::Vector2d(0.0, 1.0), Eigen::Vector2d(1.0, 0.0), step);
  EXPECT_NEAR(first.x(), 0.5, 1e-12);
  EXPECT_NEAR(first.y(), std::sqrt(3.0) / 2.0, 1e-12);
  const Eigen::Vector2d other = approach_direction(Eigen::Vector2d(0.0, -1.0), Eigen::Vector2d(1.0, 0.0), step);
  EXPECT_NEAR(other.x(), 0.5, 1e-12);
  EXPECT_NEAR(other.y(), -std::sqrt(3.0) / 2.0, 1e-12);
  // Within a step: the axis itself.
  const Eigen::Vector2d near(std::cos(0.2), std::sin(0.2));
  const Eigen::Vector2d on = approach_direction(near, Eigen::Vector2d(1.0, 0.0), step);
  EXPECT_NEAR(on.x(), 1.0, 1e-12);
  EXPECT_NEAR(on.y(), 0.0, 1e-12);
  EXPECT_NEAR(first.norm(), 1.0, 1e-12);
}
