#include "kestrel/guidance/predictive.hpp"

#include <algorithm>

namespace kestrel::guidance {

ComponentSpec Predictive::spec() {
  using C = PredictiveConfig;
  ConfigSpec<C> c;
  c.choice("prediction", &C::prediction, {{"cv", C::Model::constant_velocity}, {"ca", C::Model::constant_acceleration}})
      .describe("how the target is predicted: constant velocity, or constant acceleration (the estimate's)");
  c.param("horizon_s", &C::horizon_s)
      .with_unit("s")
      .range(0.1, 60.0)
      .describe("how far ahead to look for an intercept");
  c.param("step_s", &C::step_s).with_unit("s").range(0.001, 1.0).describe("the search grid over the horizon");
  c.param("acceleration_fraction", &C::acceleration_fraction)
      .range(0.05, 1.0)
      .describe("share of the hunter's acceleration limit the plan may use (the rest corrects errors)");
  c.param("min_time_to_go_s", &C::min_time_to_go_s)
      .with_unit("s")
      .range(0.01, 10.0)
      .describe("the rendezvous never aims to arrive sooner than this (avoids a stiff command at the end)");
  c.param("handover_m", &C::handover_m)
      .with_unit("m")
      .range(0.0, 1000.0)
      .describe("hand over to the terminal phase (align the net, fire) within this distance of the aim pose");
  c.rule("step_s <= horizon_s", {"step_s", "horizon_s"}, [](const C& k) { return k.step_s <= k.horizon_s; });
  return ComponentSpec("predictive", "Earliest reachable intercept of the predicted target, flown as a rendezvous")
      .details(
          "Each frame: predict the target over horizon_s (constant velocity or acceleration), find the earliest "
          "time tau at which the aim pose of the predicted target is reachable within the hunter's speed limit "
          "and acceleration_fraction of its acceleration limit, and command the least-effort rendezvous "
          "a = 6 ZEM / tau^2 - 2 ZEV / tau that arrives there with the target's velocity. Without an intercept "
          "within the horizon, flies at top speed towards the predicted aim pose at the horizon. Within "
          "handover_m the terminal phase aligns the net.")
      .config(std::move(c));
}

Predictive::Predictive(const ComponentInit& init) : cfg_(init.config<PredictiveConfig>()) {}

std::optional<InterceptPlan> Predictive::plan(const Engagement& e) const {
  const bool with_acceleration = cfg_.prediction == PredictiveConfig::Model::constant_acceleration;
  const auto goal_at = [&](double tau) {
    TargetMotion m = e.target;
    if (!with_acceleration) m.acceleration.setZero();
    const AimPose pose = aim_pose(m.at(tau), e.position, e.yaw, e.geometry);
    InterceptPlan plan;
    plan.point = pose.position;
    plan.point.z() = std::max(plan.point.z(), e.min_altitude);
    plan.arrival_velocity = m.velocity_at(tau);
    plan.yaw = pose.yaw;
    return plan;
  };
  FlightLimits limits = e.limits;
  limits.max_acceleration *= cfg_.acceleration_fraction;
  return earliest_intercept(e.position, e.velocity, goal_at, limits, cfg_.horizon_s, cfg_.step_s);
}

GuidanceCommand Predictive::command(const Engagement& e) {
  if (within_handover(e, cfg_.handover_m)) return terminal_phase();
  if (const auto p = plan(e)) {
    const double tau = std::max(p->time_s, cfg_.min_time_to_go_s);
    const Eigen::Vector3d a = rendezvous_acceleration(e.position, e.velocity, p->point, p->arrival_velocity, tau);
    return {e.velocity + a * e.dt, e.aim.yaw, false, std::nullopt};
  }
  // Out of reach within the horizon: close in on where the target is going.
  TargetMotion m = e.target;
  m.acceleration.setZero();
  Eigen::Vector3d far = aim_pose(m.at(cfg_.horizon_s), e.position, e.yaw, e.geometry).position;
  far.z() = std::max(far.z(), e.min_altitude);
  return {(far - e.position).normalized() * e.limits.max_speed, e.aim.yaw, false, std::nullopt};
}

}  // namespace kestrel::guidance
