// The shot: its prediction on the launcher's ballistics, whether it is worth a net, and the record
// kept of it for the shot model to be fitted again.
#include <fmt/format.h>

#include <kestrel/guidance/capture_chance.hpp>

#include "aim_planner_node.hpp"

namespace kestrel::aim {

void AimPlannerNode::fire(Context& ctx, const msg::Tracks& tracks, const msg::Track* target, FrameShot& frame,
                          double t) {
  const bool trusted = frame.spread && (cfg_.max_shot_spread_m <= 0.0 || *frame.spread <= cfg_.max_shot_spread_m);
  const auto launcher = ctx.get(kLauncher);
  const FireChances chances{worth_a_net(ctx, frame.miss, frame.probability), frame.capture_now.value_or(0.0),
                            later_value_, launcher ? static_cast<int>(launcher->nets_left) : -1};
  if (fire_.decide(t, launcher_ready(ctx, t) && trusted && target && fire_policy_->worth_a_net(chances))) {
    ++fire_count_;
    if (!first_fire_) first_fire_ = t;
    if (!frame.probability) frame.probability = hit_probability(*frame.shot, *frame.uncertainty, cfg_.net_radius_m);
    ctx.log().info("fire at t = {:.2f} s: target {}, aim error {:.2f} m, predicted miss {:.2f} m{}", t, target->id,
                   frame.error->norm(), *frame.miss,
                   frame.probability ? fmt::format(", probability {:.2f}", *frame.probability) : std::string());
    nlohmann::json record{
        {"t_s", t},
        {"predicted_miss_m", *frame.miss},
        {"probability", frame.probability ? nlohmann::json(*frame.probability) : nlohmann::json()},
        {"spread_m", *frame.spread},
        {"capture_now", frame.capture_now ? nlohmann::json(*frame.capture_now) : nlohmann::json()},
        {"later_value", later_value_ ? nlohmann::json(*later_value_) : nlohmann::json()},
        {"predicted_time_s", frame.shot->time_s},
        {"estimate_age_s", t - estimate_since_},
        {"prediction", prediction_record(*frame.shot, frame.uncertainty->lead_s, *estimate_, oscillation_)}};
    if (const auto mu = estimate_->model_probabilities(); !mu.empty()) record["model_probabilities"] = mu;
    if (const guidance::ReactionBelief* belief = predictor_->reaction()) record["reacting"] = belief->probability();
    if (const auto repeating = predictor_->repeating()) record["repeating"] = *repeating;
    shots_.push_back(std::move(record));
    ctx.publish(kFire, msg::NetFire{tracks.stamp, target->id, *frame.error});
  }
}

// The miss if the net were fired now, on the launcher's ballistics, against the target predicted
// over the time the net is open (shot_prediction: at constant velocity by default; the
// estimate's acceleration, extrapolated that far, is noisier at low speeds).
// `lead`: seconds from the estimate's time to the launch.
PredictedShot AimPlannerNode::predict_target_shot(const geometry::CameraPose& camera,
                                                  const Eigen::Vector3d& hunter_velocity, const Eigen::VectorXd& x,
                                                  double lead) const {
  using P = AimPlannerConfig::ShotPrediction;
  if (patrolling_)  // braking to the end of its line, and turning there
    return predict_shot(net_, camera, hunter_velocity, [&](double tau) {
      return patrol_->line()->predict(x.head<3>(), x.segment<3>(3), lead + tau, cfg_.patrol_max_deceleration_m_s2);
    });
  if (oscillation_)  // the oscillating axes as fitted, the others at constant velocity
    return predict_shot(net_, camera, hunter_velocity, [&](double tau) {
      return oscillation_->predict(lead + tau, x.head<3>() + x.segment<3>(3) * (lead + tau));
    });
  if (cfg_.shot_prediction == P::model)
    return predict_shot(net_, camera, hunter_velocity,
                        [&](double tau) { return estimate_->position_after(lead + tau); });
  const bool with_acceleration = cfg_.shot_prediction == P::constant_acceleration;
  const TargetMotion motion{x.head<3>(), x.segment<3>(3),
                            with_acceleration ? Eigen::Vector3d(x.segment<3>(6)) : Eigen::Vector3d::Zero()};
  return predict_shot(net_, camera, hunter_velocity, [&](double tau) { return motion.at(lead + tau); });
}

// What the shot's probability was computed from, so that its error model can be fitted again
// to the shots' outcomes (scripts/fit-shot-model): the predicted miss over the open window
// ([tau, x, y, z] rows), the estimate's position-velocity covariance (before
// shot_covariance_scale) and its state ([x y z vx vy vz ax ay az], world); with an oscillation, the
// axes it predicted and their angular frequencies.
nlohmann::json AimPlannerNode::prediction_record(const PredictedShot& shot, double lead_s,
                                                 const TargetEstimate& estimate,
                                                 const std::optional<OscillationPredictor>& oscillation) {
  nlohmann::json path = nlohmann::json::array(), covariance = nlohmann::json::array();
  for (const MissAt& m : shot.path) path.push_back({m.tau_s, m.miss.x(), m.miss.y(), m.miss.z()});
  const Eigen::MatrixXd p = estimate.covariance();
  for (int i = 0; i < 6; ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (int j = 0; j < 6; ++j) row.push_back(p(i, j));
    covariance.push_back(std::move(row));
  }
  const Eigen::VectorXd state = estimate.state();
  nlohmann::json record{{"lead_s", lead_s},
                        {"miss_path_m", std::move(path)},
                        {"position_velocity_covariance", std::move(covariance)},
                        {"estimate", std::vector<double>(state.data(), state.data() + state.size())}};
  if (oscillation) {
    nlohmann::json axes = nlohmann::json::array(), omega = nlohmann::json::array();
    for (const auto& o : oscillation->axes()) {
      axes.push_back(o.has_value());
      omega.push_back(o ? nlohmann::json(o->omega_rad_s) : nlohmann::json());
    }
    record["oscillating_axes"] = std::move(axes);
    record["oscillation_omega_rad_s"] = std::move(omega);
  }
  return record;
}

// The share of the estimate's acceleration the shot's probability expects to go on while the net
// flies, but on the axes an oscillation predicts: their prediction already turns.
Eigen::Vector3d AimPlannerNode::expected_shot_acceleration(const Eigen::VectorXd& x) const {
  if (patrolling_) return Eigen::Vector3d::Zero();  // the patrol's prediction brakes already
  Eigen::Vector3d a = cfg_.shot_acceleration_share * x.segment<3>(6);
  if (oscillation_)
    for (int axis = 0; axis < 3; ++axis)
      if (oscillation_->axes()[axis]) a[axis] = 0.0;
  return a;
}

// Whether this shot is worth a net: by probability when fire_probability is set, else by the
// predicted miss; the last net waits for a better shot than the others.
bool AimPlannerNode::worth_a_net(Context& ctx, std::optional<double> miss, std::optional<double> probability) const {
  const auto launcher = ctx.get(kLauncher);
  const bool last = launcher && launcher->nets_left == 1;
  if (cfg_.fire_probability > 0.0) {
    const double least = evader() && cfg_.flee_fire_probability > 0.0
                             ? cfg_.flee_fire_probability
                             : std::max(last ? cfg_.last_net_probability : cfg_.fire_probability,
                                        patrolling_ ? cfg_.patrol_fire_probability : 0.0);
    return probability && *probability >= least;
  }
  return miss && *miss <= (last ? cfg_.last_net_radius_m : cfg_.capture_radius_m);
}

// The launcher (when connected) fires only when loaded and not reloading.
bool AimPlannerNode::launcher_ready(Context& ctx, double t) {
  const auto launcher = ctx.get(kLauncher);
  return !launcher || (launcher->nets_left != 0 && t >= to_seconds(launcher->ready_at));
}

}  // namespace kestrel::aim
