#include "aim_planner_node.hpp"

#include <fmt/format.h>

#include <cmath>
#include <kestrel/plugin.hpp>
#include <kestrel/vehicle/airframe.hpp>

#include "sighted_track.hpp"

namespace kestrel::aim {

NodeSpec AimPlannerNode::spec() {
  using C = AimPlannerConfig;
  ConfigSpec<C> c;
  declare_flight_params(c);
  declare_shot_params(c);
  declare_recogniser_params(c);
  c.component("guidance", &C::guidance, "guidance", "hold_aim")
      .describe(
          "how the hunter closes on the target before the terminal phase aligns the net: hold_aim (the paper's: "
          "terminal from the start), pursuit, pn, frpn, predictive, run_in");
  c.component("evader_guidance", &C::evader_guidance, "guidance", "hold_aim")
      .describe(
          "flee_min_speed_m_s: the law for a target seen fleeing the hunter (an evader) instead of guidance: "
          "hold_aim (terminal from the start, at flee_aim_point_m), or run_in (stalk it outside the radius where "
          "it flees, then a pass at speed)");
  c.component("predictor", &C::predictor, "predictor", "imm_samples")
      .describe(
          "the target's futures, sampled from its world-frame estimate (target_filter imm: each model's paths by its "
          "probability): the paths a planner (guidance intercept_search) and the fire policy capture_value weigh "
          "launches on");
  c.component("fire_policy", &C::fire_policy, "fire_policy", "threshold")
      .describe(
          "whether a shot is worth a net: threshold (the aim's own thresholds, fire_probability or "
          "capture_radius_m), or capture_value (the chance of a capture now on the target's futures against what "
          "keeping the net is worth, the planner's best later launch)");
  c.component("search", &C::search, "search", "hold")
      .describe(
          "where the hunter goes once the target is lost (nothing seen for target_timeout_s): hold, turn, or "
          "back_off (to a standoff facing where it was last seen, from where the wider view finds it again)");
  c.rule("oscillation_min_omega_rad_s < oscillation_max_omega_rad_s",
         {"oscillation_min_omega_rad_s", "oscillation_max_omega_rad_s"},
         [](const C& k) { return k.oscillation_min_omega_rad_s < k.oscillation_max_omega_rad_s; });
  c.rule("aim_at swing_centre needs shot_prediction oscillation", {"aim_at", "shot_prediction"}, [](const C& k) {
    return k.aim_at == C::AimAt::target || k.shot_prediction == C::ShotPrediction::oscillation;
  });
  c.rule("swing_min_amplitude_m <= swing_max_amplitude_m", {"swing_min_amplitude_m", "swing_max_amplitude_m"},
         [](const C& k) { return k.swing_min_amplitude_m <= k.swing_max_amplitude_m; });
  c.rule("last_net_radius_m <= capture_radius_m", {"last_net_radius_m", "capture_radius_m"},
         [](const C& k) { return k.last_net_radius_m <= k.capture_radius_m; });
  // The aim plans only what the airframe flies.
  c.rule("max_speed_m_s <= the airframe's top speed (firefly 12, interceptor 20 m/s)", {"max_speed_m_s", "airframe"},
         [](const C& k) { return k.max_speed_m_s <= vehicle::airframe(k.airframe).envelope.max_speed_m_s; });
  c.rule("max_tilt_deg <= the airframe's (60 degrees)", {"max_tilt_deg", "airframe"},
         [](const C& k) { return k.max_tilt_deg <= vehicle::airframe(k.airframe).envelope.max_tilt_deg; });
  c.rule("max_acceleration_m_s2 <= the airframe's (firefly 8, interceptor 12 m/s^2)",
         {"max_acceleration_m_s2", "airframe"}, [](const C& k) {
           return k.max_acceleration_m_s2 <= vehicle::airframe(k.airframe).envelope.max_acceleration_m_s2;
         });
  c.rule("min_altitude_m <= takeoff_altitude_m", {"min_altitude_m", "takeoff_altitude_m"},
         [](const C& k) { return k.min_altitude_m <= k.takeoff_altitude_m; });
  return NodeSpec("aim_planner", "Aims the hunter so the target sits where the net opens, and fires")
      .details(
          "The paper's section 2.4: drives e_x = x_E^d - x_E to zero with the hunter's position along its heading, "
          "its height and its yaw (which keeps the target in view), through a setpoint limited in speed, "
          "acceleration and yaw rate, with the target's velocity fed forward. One setpoint per tracks message. "
          "Fires when the predicted miss stays within capture_radius_m for dwell_s, at most once per cooldown_s. The "
          "predicted miss is the least distance, while the net is open (net_flight_time_s to net_flight_time_s + "
          "net_open_s after the shot), between the net on its ballistics (net_sim's model: launched to reach the "
          "aim point, inheriting the hunter's velocity) and the target extrapolated from its world-frame estimate, "
          "so the shot leads a moving target.")
      .input(kTracks, "the tracker's tracks; the selected one is the target (camera frame)")
      .input(kOdometry,
             "the hunter's every state: the newest steers it; the one at a frame's capture time takes that frame's "
             "target to the world (kept 2 s)")
      .input(kLauncher,
             "the net launcher's state: no shot while it reloads or is empty, the last net saved for a "
             "better shot (unconnected: unlimited nets)",
             {.trigger = Trigger::latest, .optional = true})
      .output(kSetpoint, "where the hunter should be (world)")
      .output(kFire, "the order to fire the net")
      .config(std::move(c));
}

AimPlannerNode::AimPlannerNode(NodeInit& init)
    : cfg_(init.config<AimPlannerConfig>()),
      guidance_(init.make_component<guidance::Guidance>("guidance")),
      evader_guidance_(init.make_component<guidance::Guidance>("evader_guidance")),
      predictor_(init.make_component<guidance::Predictor>("predictor")),
      fire_policy_(init.make_component<FirePolicy>("fire_policy")),
      search_(init.make_component<Search>("search")) {
  if (cfg_.patrol_min_length_m > 0.0)
    patrol_.emplace(LinePatrolConfig{.window_s = cfg_.patrol_window_s,
                                     .min_length_m = cfg_.patrol_min_length_m,
                                     .max_residual_m = cfg_.patrol_max_residual_m});
}

void AimPlannerNode::process(Context& ctx) {
  if (ctx.triggered_by(kOdometry)) {
    hunter_states_.add(*ctx.get(kOdometry));
    return;
  }
  const auto tracks = ctx.get(kTracks);
  const auto hunter = ctx.get(kOdometry);
  if (!hunter) return;  // nothing to aim from yet
  const double t = to_seconds(tracks->stamp);
  const double dt = last_t_ ? std::max(0.0, t - *last_t_) : 0.0;
  last_t_ = t;
  ++frames_;
  if (!reference_) start(*hunter);

  // Nothing is engaged before the take-off height is reached: near the ground the camera sees
  // the ground at grazing angles, and whatever is tracked there is not a flying target.
  if (!armed_ && hunter->position.z() >= takeoff_.position.z() - 0.3) armed_ = true;
  // Where the camera was when the frame was taken: the tracks come out of the chain later, the
  // hunter having moved and turned on since.
  const msg::VehicleState seen_from = hunter_states_.at(tracks->stamp).value_or(*hunter);
  const geometry::CameraPose camera =
      geometry::camera_on_body(seen_from.position, seen_from.orientation, cfg_.camera_offset_m);
  const msg::Track* target = armed_ ? tracks->selected() : nullptr;
  if (target && camera.to_world(target->position()).z() < cfg_.min_target_height_m) {
    ++ground_frames_;
    target = nullptr;
  }
  // A coasting track (no detection this frame) is the tracker's extrapolation, not a sighting:
  // aiming follows sightings only, and flies on towards the last one meanwhile.
  if (target && target->misses > 0) target = nullptr;
  // An evader stays one through its estimate's restarts (it breaks out of view, and is found again
  // by the search), until nothing has been seen for flee_forget_s.
  if ((flee_.fleeing() || flee_.own_path()) && t - last_seen_ > cfg_.flee_forget_s) flee_.reset();
  if (estimate_ && t - last_seen_ > cfg_.target_timeout_s) {  // too old to predict from
    estimate_.reset();
    oscillation_.reset();
    futures_.paths.clear();
  }
  if (estimate_) estimate_->predict(dt);
  if (!target && estimate_ && (cfg_.follow_sighted_track || evader())) {
    target = sighted_track(*tracks, camera, cfg_.min_target_height_m, estimate_->state().head<3>(),
                           [&](const Eigen::Vector3d& sighting) { return expected_near(t, sighting); });
    if (target) ++sighted_track_frames_;
  }
  patrolling_ = false;
  FrameShot frame;
  if (target) frame = sight(ctx, *target, *hunter, camera, t, dt);
  steer(*hunter, t, dt, target != nullptr);

  msg::TrajectorySetpoint sp;
  sp.stamp = tracks->stamp;
  sp.position = reference_->position();
  sp.velocity = reference_->velocity();
  sp.acceleration = reference_->acceleration();
  sp.yaw = reference_->yaw();
  sp.yaw_rate = reference_->yaw_rate();
  ctx.publish(kSetpoint, std::move(sp));

  fire(ctx, *tracks, target, frame, t);
}

void AimPlannerNode::steer(const msg::VehicleState& hunter, double t, double dt, bool seen) {
  if (goal_ && seen) {
    // An evader is flown by its own law, from the frame it is recognised as one.
    if (evader() && !flown_as_evader_) evader_guidance_->reset();
    flown_as_evader_ = evader();
    guidance::Guidance& law = evader() ? *evader_guidance_ : *guidance_;
    const guidance::GuidanceCommand command = law.command(engagement(dt));
    later_value_ = command.later_value;
    if (command.terminal) {
      ++terminal_frames_;
      reference_->advance(*goal_, goal_velocity_, dt);
    } else {
      reference_->steer(command.velocity, command.yaw, dt);
    }
  } else if (const auto lookout = patrol_ && patrol_waiting(t) ? patrol_pose(hunter) : std::nullopt) {
    // Out of sight at the patrol's far end: it comes back to the end the hunter waits at.
    ++patrol_frames_;
    reference_->advance(*lookout, Eigen::Vector3d::Zero(), dt);
  } else if (goal_ && t - last_seen_ <= cfg_.target_timeout_s) {
    // A short loss: on towards the last aim pose, without feeding forward a velocity nobody sees.
    reference_->advance(*goal_, Eigen::Vector3d::Zero(), dt);
  } else if (goal_) {
    if (!holding_) {
      ++holds_;
      search_->begin(LostTarget{last_target_, last_target_velocity_, t - last_seen_, hunter.position, reference_->yaw(),
                                cfg_.min_altitude_m});
    }
    holding_ = true;
    // An evader broke past the hunter, or fled behind it: it is looked for sooner.
    const std::optional<double> turn_after =
        evader() && cfg_.flee_search_after_s >= 0.0 ? std::optional<double>(cfg_.flee_search_after_s) : std::nullopt;
    const SearchStep step = search_->step(t - last_seen_ - cfg_.target_timeout_s, turn_after);
    if (step.goal) {
      reference_->advance(*step.goal, Eigen::Vector3d::Zero(), dt);
    } else {
      if (step.yaw_rate_rad_s != 0.0) ++search_frames_;
      reference_->hold(dt, step.yaw_rate_rad_s);
    }
  } else {
    // No target yet: climb, then look ahead (once at the take-off height: a hunter on the ground
    // goes up before it goes forward).
    reference_->advance(armed_ ? lookout_ : takeoff_, Eigen::Vector3d::Zero(), dt);
  }
  if (seen)
    holding_ = false;
  else
    later_value_.reset();
}

void AimPlannerNode::start(const msg::VehicleState& hunter) {
  AimReference::Limits limits{cfg_.gain_1_s, cfg_.max_speed_m_s, cfg_.max_acceleration_m_s2,
                              cfg_.max_yaw_rate_deg_s * M_PI / 180.0, max_tilt_rad()};
  reference_.emplace(limits, hunter.position, geometry::yaw_of(hunter.orientation));
  takeoff_.position = hunter.position;
  takeoff_.position.z() = std::max(hunter.position.z(), cfg_.takeoff_altitude_m);
  takeoff_.yaw = geometry::yaw_of(hunter.orientation);
  lookout_ = takeoff_;
  lookout_.position += cfg_.search_advance_m * Eigen::Vector3d(std::cos(takeoff_.yaw), std::sin(takeoff_.yaw), 0.0);
}

void AimPlannerNode::finish(Context& ctx) {
  const std::string id = ctx.id();
  const nlohmann::json rmse =
      target_frames_ ? nlohmann::json(std::sqrt(squared_error_ / static_cast<double>(target_frames_))) : nullptr;
  const nlohmann::json first = first_fire_ ? nlohmann::json(*first_fire_) : nullptr;
  ctx.set_report_section(
      id, ReportSection()
              .quantity("frames", frames_)
              .quantity("target_frames", target_frames_)
              .metric("aim_rmse_m", rmse, "m", Better::lower)
              .quantity("fire_count", fire_count_)
              .quantity("shots", shots_)
              .quantity("futures_calibration", calibration_.report())
              .metric("time_to_first_fire_s", first, "s", Better::lower)
              .metric("holds", holds_, "", Better::lower)
              .quantity("ground_frames", ground_frames_)
              .quantity("terminal_frames", terminal_frames_)
              .quantity("search_frames", search_frames_)
              .quantity("sighted_track_frames", sighted_track_frames_)
              .quantity("patrol_frames", patrol_frames_)
              .quantity("flee_frames", flee_frames_)
              .quantity("first_seen_range_m", first_seen_range_ ? nlohmann::json(*first_seen_range_) : nullptr, "m")
              .markdown(fmt::format("Target in {} of {} frames; aim error (from the tracks) {} m RMS; {} shot(s), "
                                    "the first at {}; held {} time(s) after losing the target.\n",
                                    target_frames_, frames_,
                                    rmse.is_null() ? "n/a" : fmt::format("{:.3f}", rmse.get<double>()), fire_count_,
                                    first.is_null() ? "n/a" : fmt::format("{:.2f} s", first.get<double>()), holds_)));
}

KESTREL_REGISTER_NODE(AimPlannerNode)

}  // namespace kestrel::aim
