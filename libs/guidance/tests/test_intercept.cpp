// The earliest intercept and the rendezvous that flies it.
#include <gmock/gmock.h>

#include <kestrel/guidance/aim_reference.hpp>
#include <kestrel/guidance/intercept.hpp>

using namespace kestrel::guidance;

namespace {
const Eigen::Vector3d kRest = Eigen::Vector3d::Zero();
}

TEST(Intercept, ReachableWithinTheAccelerationBallAndTheTopSpeed) {
  const FlightLimits limits{10.0, 2.0};
  // From rest, 1 m away: a t^2 / 2 = 1 m at t = 1 s.
  EXPECT_TRUE(reachable(kRest, kRest, {1.0, 0.0, 0.0}, 1.0, limits));
  EXPECT_FALSE(reachable(kRest, kRest, {1.0, 0.0, 0.0}, 0.9, limits));
  // Moving at 2 m/s away from it: the drift must be undone first.
  EXPECT_FALSE(reachable(kRest, {-2.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, 2.0, limits));
  EXPECT_TRUE(reachable(kRest, {-2.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, 3.0, limits));
  // The top speed bounds the average: 30 m in 2 s is out of reach at 10 m/s whatever the acceleration.
  EXPECT_FALSE(reachable(kRest, kRest, {30.0, 0.0, 0.0}, 2.0, FlightLimits{10.0, 1000.0}));
}

TEST(Intercept, TheEarliestPointIsReachableAndNoEarlierOneIs) {
  const FlightLimits limits{8.0, 4.0};
  // A target crossing 10 m ahead at 4 m/s.
  const auto goal_at = [](double tau) {
    InterceptPlan p;
    p.point = Eigen::Vector3d(10.0, -5.0 + 4.0 * tau, 2.0);
    p.arrival_velocity = Eigen::Vector3d(0.0, 4.0, 0.0);
    return p;
  };
  const Eigen::Vector3d start(0.0, 0.0, 2.0);
  const auto plan = earliest_intercept(start, kRest, goal_at, limits, 10.0, 0.01);
  ASSERT_TRUE(plan);
  EXPECT_TRUE(reachable(start, kRest, plan->point, plan->time_s, limits));
  EXPECT_FALSE(reachable(start, kRest, goal_at(plan->time_s - 0.01).point, plan->time_s - 0.01, limits));
  EXPECT_GT(plan->time_s, 1.0);
  EXPECT_LT(plan->time_s, 4.0);
  EXPECT_TRUE(plan->point.isApprox(goal_at(plan->time_s).point));
  // A target that outruns the hunter for the whole horizon has no intercept.
  const auto fleeing = [](double tau) {
    InterceptPlan p;
    p.point = Eigen::Vector3d(10.0 + 12.0 * tau, 0.0, 2.0);
    return p;
  };
  EXPECT_FALSE(earliest_intercept(start, kRest, fleeing, limits, 5.0, 0.01));
}

TEST(Intercept, TheRendezvousArrivesAtThePointWithTheTargetsVelocity) {
  // Unlimited, the least-effort rendezvous is exact: flown in small steps, it arrives.
  AimReference r({1.0, 1e9, 1e9, 10.0}, kRest, 0.0);
  const Eigen::Vector3d goal(6.0, 3.0, 1.0), goal_velocity(0.0, 2.0, 0.0);
  const double arrival = 2.0, dt = 0.001;
  for (double t = 0.0; t < arrival - 1e-9; t += dt) {
    const Eigen::Vector3d a = rendezvous_acceleration(r.position(), r.velocity(), goal, goal_velocity, arrival - t);
    r.steer(r.velocity() + a * dt, 0.0, dt);
  }
  EXPECT_LT((r.position() - goal).norm(), 0.02);
  EXPECT_LT((r.velocity() - goal_velocity).norm(), 0.05);
}
