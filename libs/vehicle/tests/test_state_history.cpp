// The vehicle's recent states (state_history.hpp): the pose between two states, outside them, out
// of order, and forgotten after the span.
#include <gmock/gmock.h>

#include <cmath>

#include "kestrel/vehicle/state_history.hpp"

using namespace kestrel;

namespace {

msg::VehicleState state_at(double t_s, double x, double yaw_rad) {
  msg::VehicleState s;
  s.stamp = from_seconds(t_s);
  s.position = Eigen::Vector3d(x, 2.0 * x, 1.0);
  s.velocity = Eigen::Vector3d(x, 0.0, 0.0);
  s.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()));
  s.angular_velocity = Eigen::Vector3d(0.0, 0.0, x);
  return s;
}

double yaw_of(const Eigen::Quaterniond& q) {
  const Eigen::Vector3d forward = q * Eigen::Vector3d::UnitX();
  return std::atan2(forward.y(), forward.x());
}

}  // namespace

TEST(StateHistory, InterpolatesBetweenTheStatesAroundAStamp) {
  vehicle::StateHistory history;
  EXPECT_FALSE(history.at(from_seconds(1.0)).has_value());
  history.add(state_at(1.0, 0.0, 0.0));
  history.add(state_at(1.1, 1.0, 0.4));
  const auto s = history.at(from_seconds(1.025));
  ASSERT_TRUE(s.has_value());
  EXPECT_EQ(s->stamp, from_seconds(1.025));
  EXPECT_NEAR(s->position.x(), 0.25, 1e-9);
  EXPECT_NEAR(s->position.y(), 0.5, 1e-9);
  EXPECT_NEAR(s->velocity.x(), 0.25, 1e-9);
  EXPECT_NEAR(s->angular_velocity.z(), 0.25, 1e-9);
  EXPECT_NEAR(yaw_of(s->orientation), 0.1, 1e-9) << "a quarter of the way round";
  EXPECT_NEAR(s->orientation.norm(), 1.0, 1e-12);
  EXPECT_EQ(history.at(from_seconds(1.1))->position.x(), 1.0) << "a kept stamp gives its state";
}

TEST(StateHistory, NeverExtrapolatesAndReordersLateStates) {
  vehicle::StateHistory history;
  history.add(state_at(2.0, 2.0, 0.0));
  history.add(state_at(1.0, 1.0, 0.0));  // late, older: put in its place
  EXPECT_EQ(history.size(), 2u);
  EXPECT_NEAR(history.at(from_seconds(1.5))->position.x(), 1.5, 1e-9);
  EXPECT_EQ(history.at(from_seconds(3.0))->position.x(), 2.0) << "later than the newest: the newest";
  EXPECT_EQ(history.at(from_seconds(0.5))->position.x(), 1.0) << "earlier than the oldest: the oldest";
  history.add(state_at(2.0, 5.0, 0.0));  // the same stamp again replaces
  EXPECT_EQ(history.size(), 2u);
  EXPECT_EQ(history.at(from_seconds(2.0))->position.x(), 5.0);
}

TEST(StateHistory, ForgetsWhatIsOlderThanItsSpan) {
  vehicle::StateHistory history(0.5);
  for (int i = 0; i <= 100; ++i) history.add(state_at(0.01 * i, 0.01 * i, 0.0));
  EXPECT_EQ(history.size(), 51u) << "0.50 s to 1.00 s";
  EXPECT_NEAR(history.at(from_seconds(0.2))->position.x(), 0.5, 1e-9);
}
