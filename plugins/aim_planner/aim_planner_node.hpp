#pragma once
// The `aim_planner` node: from the tracker's selected target (camera frame) and the hunter's
// odometry to the setpoint that puts the target where the net opens, x_E^d, and the order to fire
// once the aim has held there. Its parts are components: the guidance law, or planner, chooses how
// the hunter closes in (kestrel/guidance/guidance.hpp), every law handing over to the same terminal
// phase, the paper's aim law; the predictor draws the target's futures from its estimate when a
// component reads them (intercept_search, a planner over them); the fire policy decides whether a
// shot is worth a net; the search says where the hunter goes once the target is lost. It takes off
// to takeoff_altitude_m and waits while nothing is tracked; after losing the target it flies on
// towards where it was for target_timeout_s, then searches until the tracker selects a target
// again. A selected track near the ground is clutter, never a target. The recognisers of
// particular flights (a target seen fleeing the hunter, flee_watch.hpp, flown by evader_guidance;
// oscillations and patrols) are still here, for the planner to replace.
//
//   aim_planner_node.cpp     the frame: what is seen, how the hunter is steered, the report
//   aim_planner_sight.cpp    a sighting: the world estimate, the aim pose, the shot it gives
//   aim_planner_shot.cpp     the shot: its prediction, whether it is worth a net, its record
#include <Eigen/Core>
#include <kestrel/geometry/frames.hpp>
#include <kestrel/guidance/aim_reference.hpp>
#include <kestrel/guidance/futures_calibration.hpp>
#include <kestrel/guidance/guidance.hpp>
#include <kestrel/guidance/target_futures.hpp>
#include <kestrel/messages/net_fire.hpp>
#include <kestrel/messages/net_launcher.hpp>
#include <kestrel/messages/tracks.hpp>
#include <kestrel/messages/trajectory_setpoint.hpp>
#include <kestrel/messages/vehicle_state.hpp>
#include <kestrel/net/net_model.hpp>
#include <kestrel/node.hpp>
#include <kestrel/vehicle/state_history.hpp>
#include <memory>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>

#include "aim_planner_config.hpp"
#include "fire_decision.hpp"
#include "fire_policy.hpp"
#include "flee_watch.hpp"
#include "line_patrol.hpp"
#include "motion_axis.hpp"
#include "oscillation.hpp"
#include "search.hpp"
#include "target_estimate.hpp"

namespace kestrel::aim {

using guidance::aim_pose;
using guidance::AimPose;
using guidance::AimReference;

/// What one frame's sighting gives the shot: the aim error, the predicted shot and its chances.
struct FrameShot {
  std::optional<Eigen::Vector3d> error;  ///< x_E^d - x_E, camera frame
  std::optional<double> miss, probability, spread;
  std::optional<PredictedShot> shot;
  std::optional<ShotUncertainty> uncertainty;
  std::optional<double> capture_now;  ///< on the futures, when they are drawn
};

class AimPlannerNode final : public Node {
 public:
  static constexpr Input<msg::Tracks> kTracks{"tracks"};
  static constexpr Input<msg::VehicleState> kOdometry{"odometry"};
  static constexpr Input<msg::NetLauncher> kLauncher{"launcher"};
  static constexpr Output<msg::TrajectorySetpoint> kSetpoint{"setpoint"};
  static constexpr Output<msg::NetFire> kFire{"fire"};

  static NodeSpec spec();
  explicit AimPlannerNode(NodeInit& init);
  void process(Context& ctx) override;
  void finish(Context& ctx) override;

 private:
  // aim_planner_node.cpp
  void start(const msg::VehicleState& hunter);
  /// The reference steered this frame: by the law while the target is seen, else on, searching, or taking off.
  void steer(const msg::VehicleState& hunter, double t, double dt, bool seen);

  // aim_planner_sight.cpp
  /// The target seen this frame: the estimate, the aim pose, and the shot a net launched now would make.
  FrameShot sight(Context& ctx, const msg::Track& target, const msg::VehicleState& hunter,
                  const geometry::CameraPose& camera, double t, double dt);
  guidance::Engagement engagement(double dt) const;
  Eigen::Vector3d expected_acceleration(const msg::VehicleState& hunter, const std::array<bool, 3>& waiting) const;
  bool expected_near(double t, const Eigen::Vector3d& sighting) const;
  Eigen::Vector3d flyable(Eigen::Vector3d acceleration) const;
  void stand_along_motion(const Eigen::VectorXd& x, double dt);
  void watch_patrol(double t, const Eigen::Vector3d& sighting);
  bool patrol_waiting(double t) const;
  std::optional<AimPose> patrol_pose(const msg::VehicleState& hunter);

  // aim_planner_shot.cpp
  /// The order to fire, when the shot is worth a net and the launcher is ready.
  void fire(Context& ctx, const msg::Tracks& tracks, const msg::Track* target, FrameShot& frame, double t);
  PredictedShot predict_target_shot(const geometry::CameraPose& camera, const Eigen::Vector3d& hunter_velocity,
                                    const Eigen::VectorXd& x, double lead) const;
  static nlohmann::json prediction_record(const PredictedShot& shot, double lead_s, const TargetEstimate& estimate,
                                          const std::optional<OscillationPredictor>& oscillation);
  Eigen::Vector3d expected_shot_acceleration(const Eigen::VectorXd& x) const;
  bool worth_a_net(Context& ctx, std::optional<double> miss, std::optional<double> probability) const;
  static bool launcher_ready(Context& ctx, double t);

  bool patrol_found() const { return patrol_ && patrol_->line(); }
  // Whether the target is an evader: seen fleeing the hunter, and flying no patrol.
  bool evader() const { return flee_.fleeing() && !patrol_found(); }
  // x_E^d: farther for an evader (flee_aim_point_m), outside the radius where it breaks.
  const Eigen::Vector3d& aim_point() const { return evader() ? cfg_.flee_aim_point_m : cfg_.aim_point_m; }
  double max_tilt_rad() const { return cfg_.max_tilt_deg * std::numbers::pi / 180.0; }

  AimPlannerConfig cfg_;
  vehicle::StateHistory hunter_states_;
  std::shared_ptr<guidance::Guidance> guidance_, evader_guidance_;
  bool flown_as_evader_ = false;  // whether the last command came from evader_guidance
  std::optional<AimReference> reference_;
  FireTrigger fire_{cfg_.capture_radius_m, cfg_.dwell_s, cfg_.cooldown_s};
  MotionAxis motion_axis_{cfg_.motion_axis_time_s};
  FleeWatch flee_{{cfg_.flee_min_speed_m_s, cfg_.flee_min_share, cfg_.flee_max_range_m, cfg_.flee_min_closing_m_s,
                   cfg_.flee_time_s, cfg_.flee_calm_speed_m_s, cfg_.flee_calm_time_s}};
  net::NetModel net_{{cfg_.net_open_point_m, cfg_.net_flight_time_s, cfg_.capture_radius_m, cfg_.net_open_s}};
  // The net as it catches (net_radius_m), for the capture chance on the futures.
  net::NetModel open_net_{{cfg_.net_open_point_m, cfg_.net_flight_time_s, cfg_.net_radius_m, cfg_.net_open_s}};
  std::shared_ptr<guidance::Predictor> predictor_;
  std::shared_ptr<FirePolicy> fire_policy_;
  std::shared_ptr<Search> search_;
  guidance::TargetFutures futures_;           // this frame's, from the estimate's time
  guidance::FuturesCalibration calibration_;  // how well the futures foresaw the sightings
  std::optional<double> later_value_;         // the planner's best later launch, discounted
  AimPose takeoff_, lookout_;                 // the take-off pose; ahead of it, where the first target is looked for
  Eigen::Vector3d last_target_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d last_target_velocity_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d tilt_acceleration_ = Eigen::Vector3d::Zero();  // aim_tilt target: the low-passed estimate
  std::optional<AimPose> goal_;
  std::optional<TargetEstimate> estimate_;
  std::optional<OscillationPredictor> oscillation_;  // shot_prediction oscillation
  std::optional<LinePatrol> patrol_;                 // patrol_min_length_m > 0
  bool patrolling_ = false;                          // this frame's aim pose waits at the patrol's end
  std::optional<int> patrol_end_;                    // the end waited at (PatrolLine::end)
  std::optional<double> off_line_since_;             // s: sightings off the patrol's line since
  nlohmann::json shots_ = nlohmann::json::array();   // each shot: when, its predicted miss and probability
  std::uint64_t target_id_ = 0;
  Eigen::Vector3d goal_velocity_ = Eigen::Vector3d::Zero();
  std::optional<double> last_t_, first_fire_;
  std::optional<double> first_seen_range_;  // m from the camera, at the first sighting engaged
  double last_seen_ = 0.0;
  double estimate_since_ = 0.0;  // s: when the current estimate started
  bool holding_ = false, armed_ = false;
  std::uint64_t frames_ = 0, target_frames_ = 0, fire_count_ = 0, holds_ = 0, ground_frames_ = 0, terminal_frames_ = 0,
                sighted_track_frames_ = 0, search_frames_ = 0, patrol_frames_ = 0, flee_frames_ = 0;
  double squared_error_ = 0.0;
};

}  // namespace kestrel::aim
