// intercept_search: a launch planned over the target's sampled futures.
#include <gmock/gmock.h>

#include <cmath>
#include <kestrel/guidance/aim_reference.hpp>
#include <kestrel/guidance/hold_aim.hpp>
#include <kestrel/guidance/intercept_search.hpp>

using namespace kestrel;
using namespace kestrel::guidance;

namespace {

const net::NetModel kOpenNet{net::NetParams{{0.0, 1.0, 2.0}, 0.4, 0.6, 0.3}};

// Futures of a target known exactly, at constant velocity.
TargetFutures exactly_known(const Eigen::Vector3d& p, const Eigen::Vector3d& v) {
  FuturesConfig config;
  config.samples = 16;
  config.q_velocity = config.q_acceleration = config.q_turn = 0.0;
  MotionHypothesis h;
  h.model = tracking::MotionModel::constant_velocity;
  h.mean.head<3>() = p;
  h.mean.segment<3>(3) = v;
  h.covariance = tracking::Covariance::Zero();
  return ImmSamples(config, 1).predict({h});
}

Engagement planned_engagement(const Eigen::Vector3d& hunter, const Eigen::Vector3d& velocity, double yaw,
                              const TargetFutures& futures) {
  Engagement e;
  e.dt = 1.0 / 30.0;
  e.position = hunter;
  e.velocity = velocity;
  e.yaw = yaw;
  e.geometry = {{0.0, 1.0, 2.0}, {0.1, 0.0, 0.0}};
  e.limits = {12.0, 8.0};
  e.min_altitude = 0.5;
  e.futures = &futures;
  e.net = &kOpenNet;
  return e;
}

}  // namespace

TEST(InterceptSearch, PlansALaunchThatHoldsAHoveringTargetAndClosesOnIt) {
  const auto futures = exactly_known({6.0, 0.0, 2.0}, Eigen::Vector3d::Zero());
  InterceptSearchConfig config;
  config.execution_error_m = 0.05;  // a hunter that flies its plan nearly exactly
  config.execution_error_m_s = 0.0;
  InterceptSearch planner{config};
  const GuidanceCommand command =
      planner.command(planned_engagement({0.0, 0.0, 3.0}, Eigen::Vector3d::Zero(), 0.0, futures));
  ASSERT_TRUE(planner.plan());
  EXPECT_FALSE(command.terminal);
  EXPECT_GT(planner.plan()->chance.probability, 0.9);
  ASSERT_TRUE(command.later_value);
  EXPECT_NEAR(*command.later_value, planner.plan()->value, 1e-12);
  EXPECT_LT(*command.later_value, planner.plan()->chance.probability);  // discounted for the wait
  EXPECT_GT(command.velocity.x(), 0.0);                                 // towards the target
  EXPECT_NEAR(command.yaw, 0.0, 1e-9);                                  // facing it
  // The launch point lies short of the target, above it, on the line of sight.
  EXPECT_LT(planner.plan()->point.x(), 6.0);
  EXPECT_GT(planner.plan()->point.z(), 2.0);
  EXPECT_NEAR(planner.plan()->point.y(), 0.0, 1e-6);
  // A hunter less sure of flying its plan expects less of it.
  config.execution_error_m = 0.3;
  InterceptSearch unsure{config};
  unsure.command(planned_engagement({0.0, 0.0, 3.0}, Eigen::Vector3d::Zero(), 0.0, futures));
  ASSERT_TRUE(unsure.plan());
  EXPECT_LT(unsure.plan()->chance.probability, planner.plan()->chance.probability);
}

TEST(InterceptSearch, IsTheLawThatReadsTheFutures) {
  EXPECT_TRUE(InterceptSearch{InterceptSearchConfig{}}.needs_futures());
  EXPECT_FALSE(HoldAim().needs_futures());  // the aim draws none for the paper's law
}

TEST(InterceptSearch, HandsOverToTheTerminalPhaseWhenNoLaunchIsWithinReach) {
  const auto futures = exactly_known({60.0, 0.0, 2.0}, Eigen::Vector3d::Zero());
  InterceptSearch planner{InterceptSearchConfig{}};
  const GuidanceCommand command =
      planner.command(planned_engagement({0.0, 0.0, 3.0}, Eigen::Vector3d::Zero(), 0.0, futures));
  EXPECT_TRUE(command.terminal);
  EXPECT_FALSE(planner.plan());
  EXPECT_FALSE(command.later_value);
  // And without futures at all.
  Engagement blind = planned_engagement({0.0, 0.0, 3.0}, Eigen::Vector3d::Zero(), 0.0, futures);
  blind.futures = nullptr;
  EXPECT_TRUE(planner.command(blind).terminal);
}

TEST(InterceptSearch, WaitsBeyondTheReachOfATargetThatReactsUntilALaunchIsWorthIt) {
  // A hovering target 20 m ahead, believed to flee a hunter within 5 m: no launch is within reach,
  // so the hunter waits 5 + 5 m short of it on the line of sight, 1 m above it, facing it.
  const auto futures = exactly_known({20.0, 0.0, 2.0}, Eigen::Vector3d::Zero());
  ReactionConfig reaction;
  reaction.prior = 0.9;
  reaction.radius_m = 5.0;
  const ReactionBelief belief(reaction);
  InterceptSearch planner{InterceptSearchConfig{}};
  Engagement e = planned_engagement({0.0, 0.0, 3.0}, Eigen::Vector3d::Zero(), 0.0, futures);
  e.reaction = &belief;
  const GuidanceCommand waiting = planner.command(e);
  EXPECT_FALSE(waiting.terminal);
  EXPECT_FALSE(planner.plan());
  // Pulled (gain_1_s, 1.5 /s) towards (10, 0, 3): forward, level, no sideways.
  EXPECT_NEAR(waiting.velocity.x(), 1.5 * 10.0, 1e-9);
  EXPECT_NEAR(waiting.velocity.y(), 0.0, 1e-9);
  EXPECT_NEAR(waiting.velocity.z(), 0.0, 1e-9);
  EXPECT_NEAR(waiting.yaw, 0.0, 1e-9);
  // Nearer than the wait it backs away; from the wait, the search finds a run-in at the target
  // worth the bar, and flies it.
  e.position = {16.0, 0.0, 3.0};
  EXPECT_LT(planner.command(e).velocity.x(), 0.0);
  e.position = {10.0, 0.0, 3.0};
  const GuidanceCommand run = planner.command(e);
  ASSERT_TRUE(planner.plan());
  EXPECT_GE(planner.plan()->value, InterceptSearchConfig{}.standoff_value);
  EXPECT_GT(run.velocity.x(), 0.0);
  // A target not believed to react is closed on as before: the aim law, with no launch in reach.
  const ReactionBelief unlikely(ReactionConfig{.prior = 0.1});
  e.position = {0.0, 0.0, 3.0};
  e.reaction = &unlikely;
  EXPECT_TRUE(planner.command(e).terminal);
  // A launch worth standoff_value or more is flown even at a reacting target (a hovering one 6 m
  // ahead, whose futures never flee: the launch's chance is its own).
  const auto near = exactly_known({6.0, 0.0, 2.0}, Eigen::Vector3d::Zero());
  Engagement close = planned_engagement({0.0, 0.0, 3.0}, Eigen::Vector3d::Zero(), 0.0, near);
  close.reaction = &belief;
  const GuidanceCommand flown = planner.command(close);
  ASSERT_TRUE(planner.plan());
  EXPECT_GE(planner.plan()->value, InterceptSearchConfig{}.standoff_value);
  EXPECT_GT(flown.velocity.x(), 0.0);
}

namespace {

// A target crossing 9 m ahead at 3 m/s, the hunter at rest: the time until a launch from the
// reference's own state (level, at its velocity) would catch it, with the planner's paths flown
// (the aim law where it has none, as the aim planner does), or the aim law alone. Each frame the
// futures start from the target's true state. `planned`: the frames flown on the planner's paths.
double time_to_a_catching_launch(bool plan, int& planned) {
  AimReference reference({1.0, 12.0, 8.0, M_PI, M_PI / 3.0}, {0.0, 0.0, 3.0}, 0.0);
  InterceptSearch planner{InterceptSearchConfig{}};
  const double dt = 1.0 / 30.0;
  planned = 0;
  for (int k = 0; k < 300; ++k) {
    const Eigen::Vector3d target(9.0, -4.0 + 3.0 * k * dt, 2.5), velocity(0.0, 3.0, 0.0);
    const auto futures = exactly_known(target, velocity);
    Engagement e = planned_engagement(reference.position(), reference.velocity(), reference.yaw(), futures);
    e.acceleration = reference.acceleration();
    const GuidanceCommand command = plan ? planner.command(e) : terminal_phase();
    if (command.terminal)
      reference.advance(aim_pose(target, reference.position(), reference.yaw(), e.geometry), velocity, dt);
    else
      reference.steer(command.velocity, command.yaw, dt);
    planned += !command.terminal;
    const Launch now{
        0.0,
        geometry::camera_on_body(reference.position(),
                                 Eigen::Quaterniond(Eigen::AngleAxisd(reference.yaw(), Eigen::Vector3d::UnitZ())),
                                 {0.1, 0.0, 0.0}),
        reference.velocity()};
    if (capture_chance(futures, kOpenNet, now).probability > 0.9) return k * dt;
  }
  return INFINITY;
}

}  // namespace

TEST(InterceptSearch, FlownByTheReferenceItBringsACrossingTargetIntoTheNet) {
  int planned = 0;
  const double with_plan = time_to_a_catching_launch(true, planned);
  EXPECT_LT(with_plan, 4.0);
  EXPECT_GT(planned, 0.5 * with_plan * 30.0);  // mostly on the planner's paths
  // The aim law alone gets there too (the planner is not yet the quicker: docs/experiments).
  int unused = 0;
  EXPECT_LT(time_to_a_catching_launch(false, unused), 4.0);
}

TEST(Quintic, LeavesAndArrivesAtTheStatesAskedFor) {
  const Eigen::Vector3d p0(1.0, 2.0, 3.0), v0(0.5, -1.0, 0.0), a0(2.0, 0.0, -1.0);
  const Eigen::Vector3d p1(6.0, -1.0, 4.0), v1(3.0, 0.0, 1.0), a1(0.0, 0.0, 0.0);
  const Quintic q = Quintic::between(p0, v0, a0, p1, v1, a1, 1.7);
  EXPECT_TRUE(q.position(0.0).isApprox(p0, 1e-12));
  EXPECT_TRUE(q.velocity(0.0).isApprox(v0, 1e-12));
  EXPECT_TRUE(q.acceleration(0.0).isApprox(a0, 1e-12));
  EXPECT_TRUE(q.position(1.7).isApprox(p1, 1e-9));
  EXPECT_TRUE(q.velocity(1.7).isApprox(v1, 1e-9));
  EXPECT_LT((q.acceleration(1.7) - a1).norm(), 1e-9);
  // Its velocity is its position's derivative.
  EXPECT_TRUE(((q.position(0.9 + 1e-6) - q.position(0.9 - 1e-6)) / 2e-6).isApprox(q.velocity(0.9), 1e-6));
}
