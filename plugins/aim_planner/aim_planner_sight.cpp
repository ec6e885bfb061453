// A sighting of the target: the world estimate it updates, the aim pose it gives, and the shot a
// net launched now would make.
#include <Eigen/Eigenvalues>
#include <cmath>
#include <kestrel/guidance/capture_chance.hpp>
#include <kestrel/vehicle/thrust_limit.hpp>

#include "aim_planner_node.hpp"

namespace kestrel::aim {

FrameShot AimPlannerNode::sight(Context& ctx, const msg::Track& target, const msg::VehicleState& hunter,
                                const geometry::CameraPose& camera, double t, double dt) {
  FrameShot frame;
  // The target is estimated again in the world frame, from what was seen of it there: its
  // velocity in the camera frame would include the hunter's own motion, and feeding that
  // forward would chase the hunter's tail. The track's detection, not its filtered state: a
  // filter in the camera frame lags whenever the camera turns.
  const Eigen::Vector3d in_camera = target.detection.allFinite() ? target.detection : target.position();
  const Eigen::Vector3d intruder = camera.to_world(in_camera);
  if (!first_seen_range_) first_seen_range_ = in_camera.norm();
  // A new track id is often the same intruder, its track restarted after a few misses: the
  // estimate goes on (and keeps what it knows of the velocity) when the sighting is where it
  // predicts, or where the oscillation does, within reacquire_m; a new estimate otherwise.
  const bool same_target = estimate_ && (target.id == target_id_ || expected_near(t, intruder));
  target_id_ = target.id;
  if (!same_target) {
    estimate_.emplace(intruder, TargetFilterConfig{cfg_.target_filter, cfg_.target_q, cfg_.target_q_velocity,
                                                   cfg_.target_q_turn, cfg_.target_switch_probability, cfg_.target_r});
    if (cfg_.shot_prediction == AimPlannerConfig::ShotPrediction::oscillation)
      oscillation_.emplace(OscillationConfig{cfg_.oscillation_window_s, cfg_.oscillation_min_omega_rad_s,
                                             cfg_.oscillation_max_omega_rad_s, cfg_.oscillation_min_improvement});
    estimate_since_ = t;
    calibration_.forget();
    guidance_->reset();
    evader_guidance_->reset();
    motion_axis_.reset();
    tilt_acceleration_.setZero();
  } else {
    estimate_->update(intruder);
  }
  if (oscillation_) oscillation_->add(t, intruder);
  // The futures only where a component reads them: each frame's draw costs about a millisecond.
  if (guidance_->needs_futures() || evader_guidance_->needs_futures() || fire_policy_->needs_futures()) {
    calibration_.observe(t, intruder);  // how well the futures drawn before foresaw this sighting
    predictor_->observe(dt, estimate_->state(), hunter.position);
    futures_ = predictor_->predict(estimate_->hypotheses());
    calibration_.add(t, futures_);
  }
  const Eigen::VectorXd x = estimate_->state();
  // A patrol flies its own line, away from the hunter waiting at its end as often as towards it.
  if (cfg_.flee_min_speed_m_s > 0.0 && !patrol_found()) {
    flee_.update(dt, x.head<3>(), x.segment<3>(3), hunter.position, hunter.velocity);
    if (evader()) ++flee_frames_;
  }
  const double smoothing = cfg_.aim_tilt_time_s > 0.0 ? dt / (cfg_.aim_tilt_time_s + dt) : 1.0;
  tilt_acceleration_ += smoothing * (Eigen::Vector3d(x.segment<3>(6)) - tilt_acceleration_);
  // aim_at swing_centre: wait at the centre of a wide swing for the target to come through.
  const SwingAim aimed = cfg_.aim_at == AimPlannerConfig::AimAt::swing_centre && oscillation_
                             ? swing_centre_aim(*oscillation_, x.head<3>(), x.segment<3>(3),
                                                SwingBounds{cfg_.swing_min_amplitude_m, cfg_.swing_max_amplitude_m,
                                                            cfg_.swing_max_residual_m, cfg_.swing_max_speed_m_s})
                             : SwingAim{x.head<3>(), x.segment<3>(3), {}};
  goal_velocity_ = aimed.velocity;
  goal_ =
      aim_pose(aimed.position, hunter.position, geometry::yaw_of(hunter.orientation),
               guidance::AimGeometry{aim_point(), cfg_.camera_offset_m}, expected_acceleration(hunter, aimed.waiting));
  if (cfg_.motion_axis_time_s > 0.0) stand_along_motion(x, dt);
  if (patrol_) {
    watch_patrol(t, intruder);
    if (const auto lookout = patrol_pose(hunter)) {
      patrolling_ = true;
      goal_ = lookout;
      goal_velocity_.setZero();
      ++patrol_frames_;
    }
  }
  goal_->position.z() = std::max(goal_->position.z(), cfg_.min_altitude_m);
  last_seen_ = t;
  last_target_ = x.head<3>();
  last_target_velocity_ = x.segment<3>(3);
  frame.error = aim_point() - in_camera;
  ++target_frames_;
  squared_error_ += frame.error->squaredNorm();
  // The net leaves when the order reaches the launcher, not at the capture the tracks come
  // from: in realtime the perception chain's latency (now - capture) and the link's
  // (fire_latency_s) pass first, the hunter and the target moving on meanwhile.
  const double lead = std::max(0.0, to_seconds(ctx.now()) - t) + cfg_.fire_latency_s;
  geometry::CameraPose launch = camera;
  launch.position_world += hunter.velocity * lead;
  frame.shot = predict_target_shot(launch, hunter.velocity, x, lead);
  frame.miss = frame.shot->miss.norm();
  // The estimate's position uncertainty, grown over the time the net takes to its closest
  // approach: how far it can be trusted, and the chance the net holds the target.
  const Eigen::Matrix3d ahead = estimate_->position_covariance_after(frame.shot->time_s);
  frame.spread =
      std::sqrt(std::max(0.0, Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(ahead).eigenvalues().maxCoeff()));
  frame.uncertainty = ShotUncertainty{cfg_.shot_covariance_scale * estimate_->covariance().topLeftCorner<6, 6>(), lead,
                                      expected_shot_acceleration(x),
                                      cfg_.shot_manoeuvre_m_s2 + cfg_.shot_turn_rate_rad_s * x.segment<3>(3).norm()};
  // Every frame only when it decides the shot; otherwise once, for the shot's record.
  if (cfg_.fire_probability > 0.0)
    frame.probability = hit_probability(*frame.shot, *frame.uncertainty, cfg_.net_radius_m);
  // The same launch counted on the futures (from the estimate's time: the launch is `lead` later).
  if (!futures_.empty()) {
    // A target that reacts flees the hunter flying on as it does now.
    guidance::ReactingTarget reacting;
    if (const guidance::ReactionBelief* belief = predictor_->reaction())
      reacting = {belief->probability(), &belief->config(),
                  [p = hunter.position, v = hunter.velocity](double s) { return Eigen::Vector3d(p + v * s); }};
    frame.capture_now =
        guidance::capture_chance(futures_, open_net_, guidance::Launch{lead, launch, hunter.velocity}, reacting)
            .probability;
  }
  return frame;
}

// What the guidance law sees: the reference it steers, the target's estimate, the aim pose.
guidance::Engagement AimPlannerNode::engagement(double dt) const {
  guidance::Engagement e;
  e.dt = dt;
  e.position = reference_->position();
  e.velocity = reference_->velocity();
  e.acceleration = reference_->acceleration();
  e.yaw = reference_->yaw();
  const Eigen::VectorXd x = estimate_->state();
  e.target.position = x.head<3>();
  e.target.velocity = x.segment<3>(3);
  e.target.acceleration = x.segment<3>(6);
  e.target.position_covariance = estimate_->covariance().topLeftCorner<3, 3>();
  e.aim = *goal_;
  e.geometry = {aim_point(), cfg_.camera_offset_m};
  e.limits = {cfg_.max_speed_m_s, cfg_.max_acceleration_m_s2};
  e.min_altitude = cfg_.min_altitude_m;
  e.futures = futures_.empty() ? nullptr : &futures_;
  e.net = &open_net_;
  e.reaction = predictor_->reaction();
  return e;
}

// The hunter's acceleration while it holds the aim (aim_tilt), which tilts its camera: the
// target's, which a hunter riding along with it flies; or the one its attitude holds now, the
// thrust's horizontal part over its vertical part carrying the weight.
// A hunter waiting at a swing's centre flies none of the target's acceleration along that axis.
Eigen::Vector3d AimPlannerNode::expected_acceleration(const msg::VehicleState& hunter,
                                                      const std::array<bool, 3>& waiting) const {
  using T = AimPlannerConfig::AimTilt;
  if (cfg_.aim_tilt == T::target) {
    Eigen::Vector3d followed = tilt_acceleration_;
    for (int axis = 0; axis < 3; ++axis)
      if (waiting[axis]) followed[axis] = 0.0;
    return flyable(cfg_.aim_tilt_share * followed);
  }
  if (cfg_.aim_tilt == T::hunter) {
    const Eigen::Vector3d up = hunter.orientation * Eigen::Vector3d::UnitZ();
    if (up.z() > 0.1) return guidance::kGravity_m_s2 * Eigen::Vector3d(up.x() / up.z(), up.y() / up.z(), 0.0);
  }
  return Eigen::Vector3d::Zero();
}

// Whether a sighting at time t is where the target is expected, within reacquire_m: where the
// estimate predicts it, or, on the axes that oscillate, where the oscillation does (a swing that
// left the view comes back where the fit says, not where its last velocity points).
bool AimPlannerNode::expected_near(double t, const Eigen::Vector3d& sighting) const {
  const Eigen::Vector3d predicted = estimate_->state().head<3>();
  if ((predicted - sighting).norm() <= cfg_.reacquire_m) return true;
  // last_seen_: the newest sighting, the oscillation's too.
  return oscillation_ && (oscillation_->predict(t - last_seen_, predicted) - sighting).norm() <= cfg_.reacquire_m;
}

// What the hunter flies of an acceleration: its horizontal part within max_acceleration_m_s2,
// its thrust within max_tilt_deg, as the aim's reference limits it. A target that turns harder
// than the hunter can is aimed at from the tilt the hunter reaches, not one it never reaches.
Eigen::Vector3d AimPlannerNode::flyable(Eigen::Vector3d acceleration) const {
  const double horizontal = acceleration.head<2>().norm();
  if (horizontal > cfg_.max_acceleration_m_s2) acceleration.head<2>() *= cfg_.max_acceleration_m_s2 / horizontal;
  return vehicle::tilt_limited_acceleration(acceleration, max_tilt_rad(), guidance::kGravity_m_s2);
}

// The aim pose moved round the target towards its axis of motion (motion_axis.hpp), the heading
// still on the target: the camera keeps it in view while the hunter circles.
void AimPlannerNode::stand_along_motion(const Eigen::VectorXd& x, double dt) {
  motion_axis_.update(x.segment<3>(3), dt);
  const Eigen::Vector2d bearing(std::cos(goal_->yaw), std::sin(goal_->yaw));
  const auto axis = motion_axis_.axis(bearing);
  if (!axis) return;
  const Eigen::Vector2d along = approach_direction(bearing, *axis, cfg_.orbit_step_deg * M_PI / 180.0);
  Eigen::Vector3d from = x.head<3>();  // a point behind the target along that direction
  from.head<2>() -= 3.0 * along;
  const double heading = goal_->yaw;
  goal_ = aim_pose(x.head<3>(), from, std::atan2(along.y(), along.x()), aim_point(), cfg_.camera_offset_m);
  goal_->yaw = heading;
}

// The patrol's sightings: those on its line, or, after kOffLine_s off it, a new line's.
void AimPlannerNode::watch_patrol(double t, const Eigen::Vector3d& sighting) {
  // Across the line, within 1 m; along it, within 3 m beyond an end where it turned: seen along
  // the line from the end the hunter waits at, the far end is 10 m and more deep, its depth
  // error metres.
  constexpr double kOnLine_m = 1.0, kBeyondEnd_m = 3.0, kOffLine_s = 0.5;
  const auto& line = patrol_->line();
  if (line && line->distance(sighting, kBeyondEnd_m) > kOnLine_m) {
    if (!off_line_since_) off_line_since_ = t;
    if (t - *off_line_since_ < kOffLine_s) return;  // a stray sighting, or clutter
    patrol_->reset();
    patrol_end_.reset();
  }
  off_line_since_.reset();
  patrol_->add(t, sighting);
}

// Whether a patrol, seen within patrol_timeout_s, is still waited for.
bool AimPlannerNode::patrol_waiting(double t) const {
  const auto last = patrol_->last_sighting_s();
  return patrol_->line() && last && t - *last <= cfg_.patrol_timeout_s;
}

// The aim pose that waits beyond an end of the patrol where the target turned (the one chosen
// before, else the nearest), facing along the line, the end at x_E^d.
std::optional<AimPose> AimPlannerNode::patrol_pose(const msg::VehicleState& hunter) {
  const auto& line = patrol_->line();
  if (!line) return std::nullopt;
  if (!patrol_end_) {  // once chosen, the end stays: the turn seen there leaves the window in time
    for (int end = 0; end < 2; ++end)
      if (line->turned[static_cast<std::size_t>(end)] &&
          (!patrol_end_ ||
           (line->end(end) - hunter.position).norm() < (line->end(*patrol_end_) - hunter.position).norm()))
        patrol_end_ = end;
  }
  // The lookout only sets the heading, along the line: the aim pose puts the end at x_E^d.
  constexpr double kLookout_m = 3.0;
  const Eigen::Vector3d end = line->end(*patrol_end_);
  AimPose pose = aim_pose(end, patrol_lookout(*line, *patrol_end_, kLookout_m), reference_->yaw(), aim_point(),
                          cfg_.camera_offset_m);
  pose.position.z() = std::max(pose.position.z(), cfg_.min_altitude_m);
  return pose;
}

}  // namespace kestrel::aim
