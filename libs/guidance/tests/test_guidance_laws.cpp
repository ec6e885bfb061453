// The guidance laws on engagements whose outcome is known: proportional navigation on a collision
// course commands nothing across the line of sight and meets a non-manoeuvring target; every law
// brings the hunter to the terminal phase within its limits; leading laws get there before pure
// pursuit does.
#include <gmock/gmock.h>

#include <kestrel/guidance/aim_reference.hpp>
#include <kestrel/guidance/fast_response_pn.hpp>
#include <kestrel/guidance/hold_aim.hpp>
#include <kestrel/guidance/predictive.hpp>
#include <kestrel/guidance/proportional_navigation.hpp>
#include <kestrel/guidance/pursuit.hpp>
#include <memory>

using namespace kestrel::guidance;

namespace {

const Eigen::Vector3d kZero = Eigen::Vector3d::Zero();

struct Outcome {
  std::optional<double> aligned_at;  ///< when the reference was within 0.3 m of the aim pose
  double closest_m = 1e9;            ///< nearest the reference came to the aim pose
  double max_speed = 0.0, max_acceleration = 0.0;
};

// A hunter that flies its reference exactly, against a target at constant velocity, with the aim
// planner's loop: aim pose, law, terminal phase (the paper's law) once the law hands over.
Outcome engage(Guidance& law, const Eigen::Vector3d& target_start, const Eigen::Vector3d& target_velocity,
               const FlightLimits& limits, double duration_s = 12.0) {
  const double dt = 1.0 / 30.0;
  AimReference reference({1.0, limits.max_speed, limits.max_acceleration, 2.0}, {0.0, 0.0, 3.0}, 0.0);
  Outcome out;
  Eigen::Vector3d last_v = kZero;
  for (double t = 0.0; t < duration_s; t += dt) {
    Engagement e;
    e.dt = dt;
    e.position = reference.position();
    e.velocity = reference.velocity();
    e.yaw = reference.yaw();
    e.target.position = target_start + target_velocity * t;
    e.target.velocity = target_velocity;
    e.aim = aim_pose(e.target.position, e.position, e.yaw, e.geometry);
    e.limits = limits;
    const GuidanceCommand c = law.command(e);
    if (c.terminal)
      reference.advance(e.aim, target_velocity, dt);
    else
      reference.steer(c.velocity, c.yaw, dt);
    out.max_speed = std::max(out.max_speed, reference.velocity().norm());
    out.max_acceleration = std::max(out.max_acceleration, (reference.velocity() - last_v).norm() / dt);
    last_v = reference.velocity();
    const Eigen::Vector3d target_now = target_start + target_velocity * (t + dt);
    const double off =
        (aim_pose(target_now, reference.position(), reference.yaw(), e.geometry).position - reference.position())
            .norm();
    out.closest_m = std::min(out.closest_m, off);
    if (!out.aligned_at && off < 0.3) out.aligned_at = t + dt;
  }
  return out;
}

ProportionalNavigationConfig pn_config(double handover_m = 2.0) {
  ProportionalNavigationConfig k;
  k.handover_m = handover_m;
  return k;
}

}  // namespace

TEST(ProportionalNavigation, OnACollisionCourseCommandsNothingAcrossTheLineOfSight) {
  // The target closes along the line of sight: the line of sight does not turn.
  const Eigen::Vector3d p(0, 0, 2), v(3, 0, 0), p_t(20, 0, 2), v_t(-1, 0, 0);
  const Eigen::Vector3d a = pn_acceleration(pn_config(), 8.0, p, v, p_t, v_t, kZero);
  EXPECT_NEAR(a.y(), 0.0, 1e-12);
  EXPECT_NEAR(a.z(), 0.0, 1e-12);
  // A crossing target: the command turns the pursuer towards where the target is going.
  const Eigen::Vector3d crossing = pn_acceleration(pn_config(), 8.0, p, v, p_t, {0, 3, 0}, kZero);
  EXPECT_GT(crossing.y(), 0.0);
}

TEST(ProportionalNavigation, MeetsANonManoeuvringTargetWithoutMiss) {
  // Navigation to the point itself (no hand-over): the miss distance is what PN leaves.
  ProportionalNavigation pn(pn_config(0.0));
  const Outcome out = engage(pn, {15.0, -6.0, 4.0}, {0.0, 3.0, 0.0}, {8.0, 6.0});
  EXPECT_LT(out.closest_m, 0.15);
}

TEST(GuidanceLaws, EveryLawReachesTheTerminalPhaseWithinTheLimits) {
  const FlightLimits limits{8.0, 5.0};
  std::vector<std::pair<std::string, std::unique_ptr<Guidance>>> laws;
  laws.emplace_back("hold_aim", std::make_unique<HoldAim>());
  laws.emplace_back("pursuit", std::make_unique<Pursuit>(PursuitConfig{}));
  laws.emplace_back("pn", std::make_unique<ProportionalNavigation>(pn_config()));
  laws.emplace_back("frpn", std::make_unique<FastResponsePn>(FastResponsePnConfig{}));
  laws.emplace_back("predictive", std::make_unique<Predictive>(PredictiveConfig{}));
  for (auto& [name, law] : laws) {
    const Outcome out = engage(*law, {12.0, -8.0, 4.0}, {0.0, 4.0, 0.0}, limits);
    ASSERT_TRUE(out.aligned_at) << name << ": closest " << out.closest_m << " m";
    EXPECT_LT(*out.aligned_at, 9.0) << name;
    EXPECT_LE(out.max_speed, limits.max_speed + 1e-9) << name;
    EXPECT_LE(out.max_acceleration, limits.max_acceleration + 1e-6) << name;
  }
}

TEST(GuidanceLaws, LeadingLawsAlignBeforePursuitAgainstACrossingTarget) {
  const FlightLimits limits{8.0, 5.0};
  Pursuit pursuit(PursuitConfig{});
  ProportionalNavigation pn(pn_config());
  FastResponsePn frpn(FastResponsePnConfig{});
  Predictive predictive(PredictiveConfig{});
  const Eigen::Vector3d start(14.0, -10.0, 4.0), velocity(0.0, 6.0, 0.0);
  const Outcome chased = engage(pursuit, start, velocity, limits);
  const Outcome led = engage(pn, start, velocity, limits);
  const Outcome fast = engage(frpn, start, velocity, limits);
  const Outcome planned = engage(predictive, start, velocity, limits);
  ASSERT_TRUE(chased.aligned_at && led.aligned_at && fast.aligned_at && planned.aligned_at);
  EXPECT_LT(*led.aligned_at, *chased.aligned_at);
  EXPECT_LT(*fast.aligned_at, *chased.aligned_at);
  EXPECT_LT(*planned.aligned_at, *chased.aligned_at);
}

// On a collision course (the relative velocity along the line of sight) the zero-effort miss is
// nil, and FRPN commands only its share of pursuit, G W dp; with no relative motion, the same.
TEST(FastResponsePn, OnACollisionCourseOnlyItsShareOfPursuitRemains) {
  const FastResponsePnConfig k;
  const Eigen::Vector3d p(1.0, 2.0, 3.0), dp(6.0, -2.0, 1.0);
  const Eigen::Vector3d v(0.5, 0.0, 0.0);
  const Eigen::Vector3d closing = v - dp.normalized() * 3.0;  // the target flies straight at the pursuer
  EXPECT_TRUE(frpn_acceleration(k, p, v, p + dp, closing).isApprox(k.gain * k.pursuit_weight * dp, 1e-9));
  EXPECT_TRUE(frpn_acceleration(k, p, v, p + dp, v).isApprox(k.gain * k.pursuit_weight * dp, 1e-9));
}

// A crossing target: the command is the published law, G ((1 - W) ZEM / t_go^2 + W dp), with
// t_go = |dp| / |dv|: here dp = (8, 0, 0), dv = (0, 4, 0), t_go = 2 s, ZEM = (8, 8, 0).
TEST(FastResponsePn, LeadsACrossingTargetByItsZeroEffortMiss) {
  FastResponsePnConfig k;
  k.gain = 2.0;
  k.pursuit_weight = 0.25;
  const Eigen::Vector3d a = frpn_acceleration(k, kZero, kZero, {8.0, 0.0, 0.0}, {0.0, 4.0, 0.0});
  EXPECT_TRUE(a.isApprox(Eigen::Vector3d(2.0 * (0.75 * 2.0 + 0.25 * 8.0), 2.0 * 0.75 * 2.0, 0.0), 1e-12)) << a;
}

TEST(Predictive, PlansTheEarliestReachableInterceptOfThePredictedTarget) {
  Predictive law(PredictiveConfig{});
  Engagement e;
  e.position = {0.0, 0.0, 3.0};
  e.target.position = {12.0, -6.0, 4.0};
  e.target.velocity = {0.0, 4.0, 0.0};
  e.aim = aim_pose(e.target.position, e.position, 0.0, e.geometry);
  e.limits = {8.0, 5.0};
  const auto plan = law.plan(e);
  ASSERT_TRUE(plan);
  FlightLimits planned = e.limits;
  planned.max_acceleration *= PredictiveConfig{}.acceleration_fraction;
  EXPECT_TRUE(reachable(e.position, e.velocity, plan->point, plan->time_s, planned));
  // The target's aim pose at that time, seen from here.
  const AimPose then = aim_pose(e.target.at(plan->time_s), e.position, 0.0, e.geometry);
  EXPECT_TRUE(plan->point.isApprox(then.position, 1e-9));
  const double earlier = plan->time_s - PredictiveConfig{}.step_s;
  EXPECT_FALSE(reachable(e.position, e.velocity, aim_pose(e.target.at(earlier), e.position, 0.0, e.geometry).position,
                         earlier, planned));
}
