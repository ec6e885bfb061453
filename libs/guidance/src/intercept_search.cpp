#include "kestrel/guidance/intercept_search.hpp"

#include <algorithm>
#include <cmath>
#include <kestrel/vehicle/so3.hpp>
#include <random>

namespace kestrel::guidance {

namespace {
constexpr int kPathChecks = 8;  // points along a plan's path where its limits and view are checked
}  // namespace

ComponentSpec InterceptSearch::spec() {
  using C = InterceptSearchConfig;
  ConfigSpec<C> c;
  c.param("horizon_s", &C::horizon_s).with_unit("s").range(0.1, 30.0).describe("the latest launch it plans for");
  c.param("step_s", &C::step_s).with_unit("s").range(0.02, 5.0).describe("the launch times searched, this far apart");
  c.param("max_closing_speed_m_s", &C::max_closing_speed_m_s)
      .with_unit("m/s")
      .range(0.0, 50.0)
      .describe(
          "the fastest closing speed along the line of sight at the launch: the net inherits it and is fired from "
          "farther away, before a target that reacts to a near hunter has moved");
  c.param("closing_speeds", &C::closing_speeds)
      .range(1, 20)
      .describe("how many closing speeds are searched, evenly from 0 to max_closing_speed_m_s");
  c.param("acceleration_share", &C::acceleration_share)
      .range(0.05, 1.0)
      .describe(
          "the share of the hunter's acceleration limit a new plan may use: the rest corrects it while it is flown");
  c.param("execution_error_m", &C::execution_error_m)
      .with_unit("m")
      .range(0.0, 10.0)
      .describe("the hunter's position error at a launch planned for now (standard deviation per axis)");
  c.param("execution_error_m_s", &C::execution_error_m_s)
      .with_unit("m/s")
      .range(0.0, 10.0)
      .describe("its growth per second of plan");
  c.param("max_look_away_deg", &C::max_look_away_deg)
      .with_unit("deg")
      .range(0.0, 180.0)
      .describe(
          "the hunter faces its launch heading (where the net must open), but never further than this from the "
          "target's bearing: the camera keeps it in view (half its field of view, less a margin)");
  c.param("view_half_width_deg", &C::view_half_width_deg)
      .with_unit("deg")
      .range(1.0, 90.0)
      .describe(
          "along a plan's path the target (the futures' mean) stays within this of the optical axis sideways, the "
          "hunter facing it and tilted as the path accelerates it: half the camera's field of view, less a margin");
  c.param("view_half_height_deg", &C::view_half_height_deg)
      .with_unit("deg")
      .range(1.0, 90.0)
      .describe("the same up and down: a hard acceleration pitches the camera off a target level with it");
  c.param("view_range_m", &C::view_range_m)
      .with_unit("m")
      .range(0.5, 1000.0)
      .describe("and no farther than this from the camera (its range)");
  c.param("min_range_m", &C::min_range_m)
      .with_unit("m")
      .range(0.0, 100.0)
      .describe(
          "nor nearer than this to the hunter along the path: the camera loses a target that close, and a hunter "
          "that overshoots a launch it did not fire would fly into it (the launch itself is further, where the net "
          "opens)");
  c.param("hazard_time_s", &C::hazard_time_s)
      .with_unit("s")
      .range(0.05, 1000.0)
      .describe(
          "a launch tau seconds away is worth exp(-tau / hazard_time_s) of its chance: the target may be lost, or do "
          "what no future foresaw, meanwhile");
  c.param("gain_1_s", &C::gain_1_s)
      .with_unit("1/s")
      .range(0.01, 20.0)
      .describe("pull towards a launch point nearer than min_plan_s, its velocity fed forward");
  c.param("min_plan_s", &C::min_plan_s)
      .with_unit("s")
      .range(0.0, 10.0)
      .describe(
          "a launch this near is held by a pull, not flown to on a quintic (whose accelerations grow as 1/tau^2)");
  c.param("keep_share", &C::keep_share)
      .range(0.0, 1.0)
      .describe(
          "the launch being flown is kept, its time counting down, while its value is at least this share of the "
          "best new candidate's (1: choose afresh every frame)");
  c.param("standoff_belief", &C::standoff_belief)
      .range(0.0, 1.0)
      .describe(
          "with the predictor's reacting hypothesis (reaction_prior above 0) at least this likely, a target that "
          "no launch within reach is worth standoff_value against is waited for beyond its reaction radius, not "
          "closed on: a hunter that comes nearer only makes it flee, and a run-in from beyond the radius is a launch "
          "the search finds; 0: never");
  c.param("standoff_value", &C::standoff_value)
      .range(0.0, 1.0)
      .describe("the value (chance discounted for the wait) a launch must have to be flown at a reacting target");
  c.param("standoff_margin_m", &C::standoff_margin_m)
      .with_unit("m")
      .range(0.0, 100.0)
      .describe(
          "the wait is this far beyond the reaction radius, horizontally: room to reach a closing speed that carries "
          "the net to the target before it has fled far");
  c.param("standoff_height_m", &C::standoff_height_m)
      .with_unit("m")
      .range(-10.0, 10.0)
      .describe("and this far above the target (the net falls as it flies)");
  c.param("seed", &C::seed).describe("the hunter's errors, drawn once per path");
  c.rule("step_s <= horizon_s", {"step_s", "horizon_s"}, [](const C& k) { return k.step_s <= k.horizon_s; });
  return ComponentSpec("intercept_search", "Plans the launch over the target's sampled futures")
      .details(
          "Every frame: for each launch time tau in step_s .. horizon_s and each closing speed, the launch point is "
          "where the net, fired level towards the futures' mean and inheriting the hunter's velocity (the target's "
          "mean velocity plus the closing speed along the line of sight), opens on that mean; the candidate counts "
          "when the least-jerk path (a quintic) from the hunter's reference reaches it at that velocity, level, within "
          "acceleration_share of the acceleration limit and within the speed limit, the target (the futures' mean) "
          "within view_half_width_deg, view_half_height_deg and view_range_m of its camera, and no nearer than "
          "min_range_m, all along (the hunter "
          "facing it, tilted by the path's acceleration), above the least altitude. Its "
          "chance is the share of the "
          "futures the open net holds, each counted from where it is at the launch (the hunter re-plans until then and "
          "sees the target there), the hunter off by execution_error_m + execution_error_m_s tau per path; its "
          "value that chance times exp(-tau / hazard_time_s). The hunter flies towards the best candidate's launch "
          "point along that path, facing its launch heading within "
          "max_look_away_deg of the target's bearing; with no "
          "candidate within reach it hands over to the terminal phase, the paper's aim law. The launch flown is kept, "
          "its time counting down, while its value is at least keep_share of the best new candidate's. A target the "
          "predictor believes reacts to the hunter (at least standoff_belief) is waited for standoff_margin_m beyond "
          "its reaction radius while no launch is worth standoff_value: from there a fast run-in is a launch.")
      .config(std::move(c));
}

InterceptSearch::InterceptSearch(const ComponentInit& init) : InterceptSearch(init.config<InterceptSearchConfig>()) {}

InterceptSearch::InterceptSearch(InterceptSearchConfig config) : cfg_(config) {
  std::mt19937_64 rng(static_cast<std::uint64_t>(cfg_.seed));
  std::normal_distribution<double> normal(0.0, 1.0);
  unit_errors_.resize(4096);
  for (auto& e : unit_errors_) e = Eigen::Vector3d(normal(rng), normal(rng), normal(rng));
}

bool InterceptSearch::in_view(const Eigen::Vector3d& hunter, const Eigen::Vector3d& acceleration,
                              const Eigen::Vector3d& target, const Eigen::Vector3d& camera_offset) const {
  const Eigen::Vector2d towards = (target - hunter).head<2>();
  if (towards.norm() < 0.5) return false;  // right above or below
  const Eigen::Vector3d thrust = acceleration + kGravity_m_s2 * Eigen::Vector3d::UnitZ();
  if (thrust.z() <= 0.1 * kGravity_m_s2) return false;  // a dive no attitude holds
  const Eigen::Quaterniond attitude(vehicle::attitude_along(thrust, std::atan2(towards.y(), towards.x())));
  const Eigen::Vector3d seen = geometry::camera_on_body(hunter, attitude, camera_offset).to_camera(target);
  constexpr double kDeg = M_PI / 180.0;
  return seen.z() > 0.0 && seen.norm() <= cfg_.view_range_m &&
         std::abs(seen.x()) <= seen.z() * std::tan(cfg_.view_half_width_deg * kDeg) &&
         std::abs(seen.y()) <= seen.z() * std::tan(cfg_.view_half_height_deg * kDeg);
}

std::optional<LaunchPlan> InterceptSearch::candidate(const Engagement& e, double tau, double closing,
                                                     const std::optional<Eigen::Vector2d>& line) const {
  const TargetFutures& futures = *e.futures;
  const net::NetParams& net = e.net->params();
  const Eigen::Vector3d opens_on = futures.mean(tau + net.flight_time_s);
  const Eigen::Vector3d target_velocity = futures.mean_velocity(tau + net.flight_time_s);
  LaunchPlan plan;
  if (line) {
    plan.line = *line;
  } else {
    const Eigen::Vector2d sight = (opens_on - e.position).head<2>();
    plan.line =
        sight.norm() > 1e-3 ? Eigen::Vector2d(sight.normalized()) : Eigen::Vector2d(std::cos(e.yaw), std::sin(e.yaw));
  }
  plan.time_s = tau;
  plan.closing_m_s = closing;
  plan.velocity = target_velocity;
  plan.velocity.head<2>() += closing * plan.line;
  if (plan.velocity.norm() > e.limits.max_speed) return std::nullopt;
  // The net opens at the open point relative to where the launcher was, plus what it inherited;
  // the launcher faces along the line of approach.
  const Eigen::Vector3d opens_from = opens_on - plan.velocity * net.flight_time_s;
  const Eigen::Vector3d behind(opens_from.x() - plan.line.x(), opens_from.y() - plan.line.y(), opens_from.z());
  const AimPose pose = aim_pose(opens_from, behind, e.yaw, net.open_point_camera, e.geometry.camera_offset_body);
  plan.point = pose.position;
  plan.yaw = pose.yaw;
  if (plan.point.z() < e.min_altitude) return std::nullopt;
  // The least-jerk path from the reference's state to the launch's, arriving level (no
  // acceleration, as the launch was placed): within the limits all along.
  plan.path =
      Quintic::between(e.position, e.velocity, e.acceleration, plan.point, plan.velocity, Eigen::Vector3d::Zero(), tau);
  // A new plan keeps a margin of the acceleration for its corrections, which the launch already
  // flown may take; the reference may be accelerating harder still, and the path starts from it.
  const double share = line ? 1.0 : cfg_.acceleration_share;
  const double reach = std::max(share * e.limits.max_acceleration, e.acceleration.norm());
  // Within the limits all along, the target in view and not too near (a plan that would lose it
  // is not flown: the paper's aim law, which keeps it in view, takes over when none is left).
  for (int k = 1; k <= kPathChecks; ++k) {
    const double s = tau * k / kPathChecks;
    const Eigen::Vector3d a = plan.path.acceleration(s), hunter = plan.path.position(s), target = futures.mean(s);
    if (a.norm() > reach || plan.path.velocity(s).norm() > e.limits.max_speed) return std::nullopt;
    if ((target - hunter).norm() < cfg_.min_range_m || !in_view(hunter, a, target, e.geometry.camera_offset_body))
      return std::nullopt;
  }
  const double sigma = cfg_.execution_error_m + cfg_.execution_error_m_s * tau;
  std::vector<Eigen::Vector3d> errors(futures.size());
  for (std::size_t i = 0; i < errors.size(); ++i) errors[i] = sigma * unit_errors_[i % unit_errors_.size()];
  const geometry::CameraPose launcher =
      geometry::camera_on_body(plan.point, Eigen::Quaterniond(Eigen::AngleAxisd(plan.yaw, Eigen::Vector3d::UnitZ())),
                               e.geometry.camera_offset_body);
  // The hunter re-plans until the launch: the target is seen where it is then.
  // A target that reacts flees the hunter along this path, then from the launch on.
  ReactingTarget reacting;
  if (e.reaction && e.reaction->probability() > 0.0)
    reacting = {e.reaction->probability(), &e.reaction->config(), [&plan, tau](double s) {
                  return s <= tau ? plan.path.position(s) : Eigen::Vector3d(plan.point + plan.velocity * (s - tau));
                }};
  plan.chance = capture_chance(futures, *e.net, Launch{tau, launcher, plan.velocity}, reacting, errors, true);
  plan.value = plan.chance.probability * std::exp(-tau / cfg_.hazard_time_s);
  return plan;
}

GuidanceCommand InterceptSearch::standoff(const Engagement& e) const {
  const Eigen::Vector3d target = e.futures->mean(0.0), target_velocity = e.futures->mean_velocity(0.0);
  Eigen::Vector2d sight = (target - e.position).head<2>();
  sight = sight.norm() > 1e-3 ? Eigen::Vector2d(sight.normalized()) : Eigen::Vector2d(std::cos(e.yaw), std::sin(e.yaw));
  const double range = e.reaction->config().radius_m + cfg_.standoff_margin_m;
  Eigen::Vector3d wait = target;
  wait.head<2>() -= range * sight;
  wait.z() = std::max(target.z() + cfg_.standoff_height_m, e.min_altitude);
  GuidanceCommand command;
  command.velocity = target_velocity + cfg_.gain_1_s * (wait - e.position);
  command.yaw = std::atan2(sight.y(), sight.x());
  return command;
}

GuidanceCommand InterceptSearch::command(const Engagement& e) {
  std::optional<LaunchPlan> flown = std::move(plan_);  // the launch flown until now
  plan_.reset();
  if (!e.futures || e.futures->empty() || !e.net) return terminal_phase();
  const net::NetParams& net = e.net->params();
  const double latest = std::min(cfg_.horizon_s, e.futures->horizon_s() - net.flight_time_s - net.open_for_s);
  double best_score = -1.0;
  for (double tau = cfg_.step_s; tau <= latest + 1e-9; tau += cfg_.step_s)
    for (std::int64_t k = 0; k < cfg_.closing_speeds; ++k) {
      const double closing =
          cfg_.closing_speeds > 1 ? cfg_.max_closing_speed_m_s * k / static_cast<double>(cfg_.closing_speeds - 1) : 0.0;
      const auto plan = candidate(e, tau, closing);
      if (!plan) continue;
      // Far from any capture, the nearest launch leads on (a small share of its closeness).
      const double score =
          (plan->chance.probability + 0.05 * plan->chance.closeness) * std::exp(-tau / cfg_.hazard_time_s);
      if (score > best_score) {
        best_score = score;
        plan_ = plan;
      }
    }
  // The launch flown so far, its time counted down, on this frame's futures.
  if (flown && flown->time_s - e.dt >= 0.5 * cfg_.step_s) {
    const auto kept = candidate(e, flown->time_s - e.dt, flown->closing_m_s, flown->line);
    if (kept && (!plan_ || kept->value >= cfg_.keep_share * plan_->value)) plan_ = kept;
  }
  // A target that flees a near hunter is waited for beyond its reach until a launch is worth it.
  if (e.reaction && e.reaction->probability() >= cfg_.standoff_belief && cfg_.standoff_belief > 0.0 &&
      (!plan_ || plan_->value < cfg_.standoff_value)) {
    GuidanceCommand command = standoff(e);
    if (plan_) command.later_value = plan_->value;
    plan_.reset();  // a plan not flown is not kept
    return command;
  }
  if (!plan_) return terminal_phase();
  GuidanceCommand command;
  // The launch's heading, turned towards the target's bearing as far as the camera needs.
  const Eigen::Vector2d towards = (e.futures->mean(0.0) - e.position).head<2>();
  command.yaw = plan_->yaw;
  if (towards.norm() > 0.05) {
    const double bearing = std::atan2(towards.y(), towards.x());
    const double off = angle_difference(plan_->yaw, bearing), most = cfg_.max_look_away_deg * M_PI / 180.0;
    command.yaw = bearing + std::clamp(off, -most, most);
  }
  if (plan_->time_s <= cfg_.min_plan_s) {
    command.velocity = plan_->velocity + cfg_.gain_1_s * (plan_->point - e.position);
  } else {
    command.velocity = plan_->path.velocity(std::min(plan_->time_s, std::max(e.dt, 0.02)));
  }
  command.later_value = plan_->value;
  return command;
}

}  // namespace kestrel::guidance
