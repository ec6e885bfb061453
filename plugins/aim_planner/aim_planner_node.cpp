// The `aim_planner` node: from the tracker's selected target (camera frame) and the hunter's
// odometry to the setpoint that puts the target where the net opens, x_E^d, and the order to fire
// once the aim has held there. A guidance component (kestrel/guidance/guidance.hpp) chooses how
// the hunter closes in; every law hands over to the same terminal phase, the paper's aim law. A target
// seen fleeing the hunter (an evader, flee_watch.hpp) is flown by a second one, evader_guidance. Takes off to
// takeoff_altitude_m and waits while nothing is tracked; after losing the target it flies on towards where it was for
// target_timeout_s, then holds (or searches by turning slowly) until the tracker selects a target again. A selected
// track near the ground is clutter, never a target. Two more components: the predictor draws the target's futures
// from its estimate when a component reads them (guidance intercept_search, a planner over them), and the fire policy
// decides whether a shot is worth a net (the aim's thresholds, or a capture now against the planner's later value).
#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <kestrel/geometry/frames.hpp>
#include <kestrel/guidance/aim_reference.hpp>
#include <kestrel/guidance/capture_chance.hpp>
#include <kestrel/guidance/guidance.hpp>
#include <kestrel/guidance/target_futures.hpp>
#include <kestrel/messages/net_fire.hpp>
#include <kestrel/messages/net_launcher.hpp>
#include <kestrel/messages/tracks.hpp>
#include <kestrel/messages/trajectory_setpoint.hpp>
#include <kestrel/messages/vehicle_state.hpp>
#include <kestrel/plugin.hpp>
#include <kestrel/tracking/kalman_filter.hpp>
#include <kestrel/vehicle/airframe.hpp>
#include <kestrel/vehicle/state_history.hpp>
#include <kestrel/vehicle/thrust_limit.hpp>
#include <numbers>
#include <optional>

#include "fire_decision.hpp"
#include "fire_policy.hpp"
#include "flee_watch.hpp"
#include "line_patrol.hpp"
#include "lost_search.hpp"
#include "motion_axis.hpp"
#include "oscillation.hpp"
#include "sighted_track.hpp"
#include "target_estimate.hpp"

namespace kestrel::aim {

using guidance::aim_pose;
using guidance::AimPose;
using guidance::AimReference;

struct AimPlannerConfig {
  enum class WhenLost { hold, search, back_off };
  enum class ShotPrediction { constant_velocity, constant_acceleration, model, oscillation };
  enum class AimTilt { level, target, hunter };
  enum class AimAt { target, swing_centre };
  Eigen::Vector3d aim_point_m{0.0, 1.0, 2.0};
  Eigen::Vector3d net_open_point_m{0.0, 1.0, 2.0};
  Eigen::Vector3d camera_offset_m{0.1, 0.0, 0.0};
  std::string airframe = "firefly";
  double gain_1_s = 1.0;
  double max_speed_m_s = 5.0;
  double max_acceleration_m_s2 = 4.0;
  double max_tilt_deg = 60.0;
  double max_yaw_rate_deg_s = 90.0;
  double takeoff_altitude_m = 2.0;
  double search_advance_m = 0.0;
  double min_altitude_m = 0.5;
  double min_target_height_m = 0.5;
  double target_timeout_s = 1.0;
  double reacquire_m = 1.0;
  bool follow_sighted_track = false;
  double target_q = 1.0;
  double target_r = 1.0;
  TargetFilterConfig::Model target_filter = TargetFilterConfig::Model::constant_acceleration;
  double target_q_velocity = 1.0;
  double target_q_turn = 10.0;
  double target_switch_probability = 0.01;
  WhenLost when_lost = WhenLost::hold;
  double search_yaw_rate_deg_s = 20.0;
  double back_off_distance_m = 5.0;
  double back_off_height_m = 0.5;
  double back_off_search_after_s = -1.0;  // < 0: the back-off holds its standoff
  double capture_radius_m = 0.5;
  double last_net_radius_m = 0.3;
  double fire_probability = 0.0;
  double max_shot_spread_m = 0.7;
  double fire_latency_s = 0.0;
  double last_net_probability = 0.9;
  double net_radius_m = 0.6;
  // The shot's error model as scripts/fit-shot-model fitted it to 522 shots of the capture
  // benchmark's tuning engagements (docs/control.md).
  double shot_manoeuvre_m_s2 = 0.5;
  double shot_turn_rate_rad_s = 0.5;
  double shot_acceleration_share = 0.75;
  double shot_covariance_scale = 0.25;
  ShotPrediction shot_prediction = ShotPrediction::constant_velocity;
  double oscillation_window_s = 2.5;
  double oscillation_min_omega_rad_s = 0.5;
  double oscillation_max_omega_rad_s = 8.0;
  double oscillation_min_improvement = 2.0;
  AimAt aim_at = AimAt::target;
  double swing_min_amplitude_m = 1.0;
  double swing_max_amplitude_m = 4.0;
  double swing_max_residual_m = 0.1;
  double swing_max_speed_m_s = 1000.0;
  double dwell_s = 0.5;
  double motion_axis_time_s = 0.0;
  double patrol_min_length_m = 0.0;  // 0: never wait at a patrol's end
  double patrol_window_s = 8.0;
  double patrol_max_residual_m = 0.12;
  double patrol_timeout_s = 6.0;
  double patrol_max_deceleration_m_s2 = 10.0;
  double patrol_fire_probability = 0.8;
  double flee_min_speed_m_s = 0.0;  // 0: never treat the target as an evader
  double flee_min_share = 0.7;
  double flee_max_range_m = 8.0;
  double flee_time_s = 0.25;
  double flee_min_closing_m_s = 1.0;
  Eigen::Vector3d flee_aim_point_m{0.0, 1.6, 3.2};
  double flee_search_after_s = 1.5;
  double flee_forget_s = 10.0;
  double flee_fire_probability = 0.0;
  double flee_calm_speed_m_s = 0.0;
  double flee_calm_time_s = 1.5;
  AimTilt aim_tilt = AimTilt::level;
  double aim_tilt_share = 1.0;
  double aim_tilt_time_s = 0.5;
  double orbit_step_deg = 30.0;
  double net_flight_time_s = 0.4;
  double net_open_s = 0.3;
  double cooldown_s = 3.0;
  ComponentConfig guidance;
  ComponentConfig evader_guidance;
  ComponentConfig predictor;
  ComponentConfig fire_policy;
};

class AimPlannerNode final : public Node {
 public:
  static constexpr Input<msg::Tracks> kTracks{"tracks"};
  static constexpr Input<msg::VehicleState> kOdometry{"odometry"};
  static constexpr Input<msg::NetLauncher> kLauncher{"launcher"};
  static constexpr Output<msg::TrajectorySetpoint> kSetpoint{"setpoint"};
  static constexpr Output<msg::NetFire> kFire{"fire"};

  static NodeSpec spec() {
    using C = AimPlannerConfig;
    ConfigSpec<C> c;
    c.param("aim_point_m", &C::aim_point_m)
        .with_unit("m")
        .range(-50.0, 50.0)
        .describe(
            "x_E^d: where the hunter holds the target, in the camera frame (x right, y down, z forward); the paper's "
            "[0, 1, 2], where its net opens");
    c.param("net_open_point_m", &C::net_open_point_m)
        .with_unit("m")
        .range(-50.0, 50.0)
        .describe(
            "where the launcher's net reaches its widest opening, in the camera frame at the launch (net_sim's "
            "open_point_m), for the predicted shot; it flies on while open, so a target held beyond it is swept");
    c.param("camera_offset_m", &C::camera_offset_m)
        .with_unit("m")
        .range(-10.0, 10.0)
        .describe("the camera's position in the body frame (as the camera node has it)");
    c.param("airframe", &C::airframe)
        .describe(
            "the hunter's airframe (kestrel/vehicle/airframe.hpp): the speed and acceleration limits may not exceed "
            "its envelope (firefly 12 m/s, 8 m/s^2; interceptor 20 m/s, 12 m/s^2)")
        .allowed = vehicle::airframe_names();
    c.param("gain_1_s", &C::gain_1_s)
        .with_unit("1/s")
        .range(0.01, 100.0)
        .describe("pull of the setpoint towards the aim pose");
    c.param("max_speed_m_s", &C::max_speed_m_s).with_unit("m/s").range(0.1, 100.0).describe("setpoint speed limit");
    c.param("max_acceleration_m_s2", &C::max_acceleration_m_s2)
        .with_unit("m/s^2")
        .range(0.1, 100.0)
        .describe("setpoint acceleration limit");
    c.param("max_tilt_deg", &C::max_tilt_deg)
        .with_unit("deg")
        .range(5.0, 85.0)
        .describe(
            "setpoint tilt limit: the thrust that flies the setpoint's acceleration (it plus gravity) leans no further "
            "from vertical, its horizontal part giving way; the aim pose of aim_tilt: target assumes no more");
    c.param("max_yaw_rate_deg_s", &C::max_yaw_rate_deg_s)
        .with_unit("deg/s")
        .range(1.0, 1000.0)
        .describe("setpoint yaw-rate limit");
    c.param("takeoff_altitude_m", &C::takeoff_altitude_m)
        .with_unit("m")
        .range(0.0, 1000.0)
        .describe("height to climb to and wait at before the first target");
    c.param("search_advance_m", &C::search_advance_m)
        .with_unit("m")
        .range(0.0, 1000.0)
        .describe(
            "before the first target: fly this far ahead along the take-off heading, at take-off height, "
            "looking for it");
    c.param("min_altitude_m", &C::min_altitude_m)
        .with_unit("m")
        .range(0.0, 1000.0)
        .describe("the setpoint never goes lower, whatever the target does");
    c.param("min_target_height_m", &C::min_target_height_m)
        .with_unit("m")
        .range(-1000.0, 1000.0)
        .describe("a selected track lower than this (world z) is ground clutter, not a target");
    c.param("target_timeout_s", &C::target_timeout_s)
        .with_unit("s")
        .range(0.0, 3600.0)
        .describe("after losing the target, keep flying towards it this long, then hold or search");
    c.param("reacquire_m", &C::reacquire_m)
        .with_unit("m")
        .range(0.0, 100.0)
        .describe(
            "a new track whose sighting lies within this of the world estimate's prediction continues that estimate "
            "(the same intruder, its track restarted); 0: every new track starts a new estimate");
    c.param("follow_sighted_track", &C::follow_sighted_track)
        .describe(
            "when the selected track has no detection this frame (it coasts, or is ground clutter), follow another "
            "track's detection where the world estimate expects the target, within reacquire_m: a camera that pitches "
            "fast breaks its tracks in the camera frame, and the selector keeps the old, coasting one; false: follow "
            "the selected track only (the paper's)");
    c.param("target_q", &C::target_q)
        .with_unit("m^2/s^5")
        .range(0.0, 1e6)
        .describe("world-frame target estimate: process noise of its constant-acceleration Kalman filter");
    c.param("target_r", &C::target_r)
        .with_unit("m^2")
        .range(1e-9, 1e6)
        .describe("world-frame target estimate: measurement noise");
    c.choice("target_filter", &C::target_filter,
             {{"cv", TargetFilterConfig::Model::constant_velocity},
              {"ca", TargetFilterConfig::Model::constant_acceleration},
              {"imm", TargetFilterConfig::Model::imm}})
        .describe(
            "world-frame target estimate: a constant-acceleration Kalman filter (q = target_q), a constant-velocity "
            "one "
            "(target_q_velocity), or an IMM of constant velocity, constant acceleration and a coordinated turn "
            "(target_q_turn)");
    c.param("target_q_velocity", &C::target_q_velocity)
        .with_unit("m^2/s^3")
        .range(0.0, 1e7)
        .describe("cv, imm: the constant-velocity model's white-noise acceleration intensity");
    c.param("target_q_turn", &C::target_q_turn)
        .with_unit("m^2/s^5")
        .range(0.0, 1e7)
        .describe("imm: the coordinated-turn model's white-noise jerk intensity");
    c.param("target_switch_probability", &C::target_switch_probability)
        .range(0.0, 0.5)
        .describe("imm: chance per frame that the target changes model");
    c.choice("when_lost", &C::when_lost,
             {{"hold", C::WhenLost::hold}, {"search", C::WhenLost::search}, {"back_off", C::WhenLost::back_off}})
        .describe(
            "after the timeout: hold position and heading; hold position and turn slowly; or back off to a standoff "
            "facing where the target was last seen, where the wider view finds it again");
    c.param("search_yaw_rate_deg_s", &C::search_yaw_rate_deg_s)
        .with_unit("deg/s")
        .range(0.0, 360.0)
        .describe("search: turn rate, towards the side the target was last heading");
    c.param("back_off_distance_m", &C::back_off_distance_m)
        .with_unit("m")
        .range(0.5, 100.0)
        .describe("back_off: horizontal distance of the standoff from where the target was last seen");
    c.param("back_off_height_m", &C::back_off_height_m)
        .with_unit("m")
        .range(-100.0, 100.0)
        .describe("back_off: height of the standoff above where the target was last seen");
    c.param("back_off_search_after_s", &C::back_off_search_after_s)
        .with_unit("s")
        .range(-1.0, 1000.0)
        .describe(
            "back_off: this long after the loss with nothing seen, turn at search_yaw_rate_deg_s as search does; "
            "< 0: hold the standoff");
    c.param("capture_radius_m", &C::capture_radius_m)
        .with_unit("m")
        .range(0.01, 10.0)
        .describe("fire when |x_E^d - x_E| stays below this (the net's capture radius)");
    c.choice("shot_prediction", &C::shot_prediction,
             {{"cv", C::ShotPrediction::constant_velocity},
              {"ca", C::ShotPrediction::constant_acceleration},
              {"model", C::ShotPrediction::model},
              {"oscillation", C::ShotPrediction::oscillation}})
        .describe(
            "the target's motion while the net flies, for the predicted miss: constant velocity, the estimate's "
            "acceleration held, the estimate's own model (imm: each model's prediction by its probability, the "
            "coordinated turn's among them), or an oscillation about a centre fitted axis by axis to its recent "
            "motion (oscillation_* parameters; turns, figure-8s, lines flown back and forth)");
    c.param("oscillation_window_s", &C::oscillation_window_s)
        .with_unit("s")
        .range(0.1, 60.0)
        .describe("shot_prediction oscillation: the recent motion the oscillation is fitted to");
    c.param("oscillation_min_omega_rad_s", &C::oscillation_min_omega_rad_s)
        .with_unit("rad/s")
        .range(0.05, 100.0)
        .describe("shot_prediction oscillation: the slowest oscillation looked for (its angular frequency)");
    c.param("oscillation_max_omega_rad_s", &C::oscillation_max_omega_rad_s)
        .with_unit("rad/s")
        .range(0.05, 100.0)
        .describe("shot_prediction oscillation: the quickest oscillation looked for");
    c.param("oscillation_min_improvement", &C::oscillation_min_improvement)
        .range(1.0, 1e6)
        .describe(
            "shot_prediction oscillation: an axis oscillates only where the sinusoid's mean squared residual is this "
            "many times below a parabola's (constant acceleration) over the same sightings; elsewhere it is predicted "
            "at constant velocity");
    c.choice("aim_at", &C::aim_at, {{"target", C::AimAt::target}, {"swing_centre", C::AimAt::swing_centre}})
        .describe(
            "what the aim pose puts at x_E^d: the target (the paper's), or, on each axis where the target swings "
            "(shot_prediction oscillation) by swing_min_amplitude_m to swing_max_amplitude_m, the centre of its swing: "
            "the hunter waits there, facing it, for the target to come through the net, instead of chasing a swing "
            "it cannot turn with");
    c.param("swing_min_amplitude_m", &C::swing_min_amplitude_m)
        .with_unit("m")
        .range(0.0, 1000.0)
        .describe("aim_at swing_centre: the least amplitude of a swing the hunter waits at the centre of");
    c.param("swing_max_amplitude_m", &C::swing_max_amplitude_m)
        .with_unit("m")
        .range(0.0, 1000.0)
        .describe(
            "aim_at swing_centre: the largest: a wider swing leaves the camera's view from the centre for longer than "
            "the tracker keeps it, and is followed");
    c.param("swing_max_residual_m", &C::swing_max_residual_m)
        .with_unit("m")
        .range(0.0, 1000.0)
        .describe(
            "aim_at swing_centre: the largest RMS residual of the swing's sinusoid: a less regular swing (a line flown "
            "back and forth at a cruise) comes through the centre at a time the fit does not predict well enough, "
            "and is followed");
    c.param("swing_max_speed_m_s", &C::swing_max_speed_m_s)
        .with_unit("m/s")
        .range(0.0, 1000.0)
        .describe(
            "aim_at swing_centre: the fastest swing waited for (peak speed over its swinging axes): a faster one "
            "crosses the net's opening too quickly for the fit's timing, and is followed");
    c.param("fire_probability", &C::fire_probability)
        .range(0.0, 1.0)
        .describe(
            "fire when the probability that the open net holds the target (the share of its predicted paths that "
            "meet the net while open, shot_* parameters) reaches this, instead of the capture_radius_m test; 0: the "
            "radius test");
    c.param("max_shot_spread_m", &C::max_shot_spread_m)
        .with_unit("m")
        .range(0.0, 100.0)
        .describe(
            "no shot while the estimate's prediction at the closest approach is more uncertain than this (the standard "
            "deviation along its most uncertain direction): a fresh estimate knows where the target is but not yet "
            "where it goes (0.7 m: shots within it caught 84 % of the time, those beyond it 45 %); 0: no such test");
    c.param("fire_latency_s", &C::fire_latency_s)
        .with_unit("s")
        .range(0.0, 10.0)
        .describe(
            "from the order to the launch, beyond the perception chain's latency (which the aim measures): the "
            "link to a launcher behind an autopilot; the shot is predicted from that much later");
    c.param("last_net_probability", &C::last_net_probability)
        .range(0.0, 1.0)
        .describe("with fire_probability: the probability the last net waits for");
    c.param("net_radius_m", &C::net_radius_m)
        .with_unit("m")
        .range(0.01, 10.0)
        .describe("the open net's radius (as net_sim has it), for the shot's probability");
    c.param("shot_manoeuvre_m_s2", &C::shot_manoeuvre_m_s2)
        .with_unit("m/s^2")
        .range(0.0, 100.0)
        .describe(
            "the shot's probability: standard deviation per axis of an acceleration the prediction does not foresee, "
            "held while the net flies (the target's manoeuvre)");
    c.param("shot_turn_rate_rad_s", &C::shot_turn_rate_rad_s)
        .with_unit("rad/s")
        .range(0.0, 100.0)
        .describe(
            "the shot's probability: the unforeseen acceleration grows by this times the target's speed (a turn at "
            "this rate): a fast target's manoeuvre moves it further");
    c.param("shot_acceleration_share", &C::shot_acceleration_share)
        .range(0.0, 1.0)
        .describe(
            "the shot's probability: the share of the estimate's acceleration expected to go on while the net flies "
            "(it moves the predicted path)");
    c.param("shot_covariance_scale", &C::shot_covariance_scale)
        .range(0.0, 100.0)
        .describe("the shot's probability: the estimate's position and velocity covariance is taken this many times");
    c.param("last_net_radius_m", &C::last_net_radius_m)
        .with_unit("m")
        .range(0.01, 10.0)
        .describe("the last net is fired only on a predicted miss within this (a better shot than the others)");
    c.param("net_flight_time_s", &C::net_flight_time_s)
        .with_unit("s")
        .range(0.0, 10.0)
        .describe("launch to widest opening: the shot leads the target by this much (0: no lead)");
    c.param("net_open_s", &C::net_open_s)
        .with_unit("s")
        .range(0.0, 10.0)
        .describe("how long the net stays open, flying on, after its widest opening (net_sim's open_for_s)");
    c.param("dwell_s", &C::dwell_s)
        .with_unit("s")
        .range(0.0, 60.0)
        .describe("how long the aim must hold before firing");
    c.param("motion_axis_time_s", &C::motion_axis_time_s)
        .with_unit("s")
        .range(0.0, 100.0)
        .describe(
            "stand on the target's axis of motion (the principal direction of its horizontal velocity, averaged over "
            "this long), so that the net sweeps along its path and only its manoeuvre across it counts against the "
            "net's radius; 0: stand on the line of sight, where the hunter happens to be (the paper's)");
    c.param("patrol_min_length_m", &C::patrol_min_length_m)
        .with_unit("m")
        .range(0.0, 1000.0)
        .describe(
            "wait for a target that flies a line back and forth (a patrol) at least this long beyond the end where it "
            "was seen to turn, facing along the line with the end at x_E^d: it comes straight at the net and stops "
            "where the net opens, instead of crossing it at its cruise; 0: never (the paper's)");
    c.param("patrol_window_s", &C::patrol_window_s)
        .with_unit("s")
        .range(0.5, 600.0)
        .describe("patrol_min_length_m: the sightings the patrol's line is fitted to");
    c.param("patrol_max_residual_m", &C::patrol_max_residual_m)
        .with_unit("m")
        .range(0.0, 100.0)
        .describe("patrol_min_length_m: the largest RMS distance of the sightings off the line");
    c.param("patrol_timeout_s", &C::patrol_timeout_s)
        .with_unit("s")
        .range(0.0, 3600.0)
        .describe(
            "patrol_min_length_m: how long the hunter waits at the patrol's end with the target out of sight (beyond "
            "the camera's range at the far end) before it backs off as when_lost says");
    c.param("patrol_max_deceleration_m_s2", &C::patrol_max_deceleration_m_s2)
        .with_unit("m/s^2")
        .range(0.1, 100.0)
        .describe(
            "patrol_min_length_m: the shot predicts the target braking into its turn as hard as its turns showed, at "
            "most this hard");
    c.param("patrol_fire_probability", &C::patrol_fire_probability)
        .range(0.0, 1.0)
        .describe(
            "patrol_min_length_m, with fire_probability: the probability a shot waits for while the hunter waits at "
            "the patrol's end (the target comes back every turn: a marginal shot is not worth a net)");
    c.param("flee_min_speed_m_s", &C::flee_min_speed_m_s)
        .with_unit("m/s")
        .range(0.0, 100.0)
        .describe(
            "a target that moves away from the hunter along the line of sight at least this fast (and at least "
            "flee_min_share of its speed) while the hunter closes on it (flee_min_closing_m_s), within "
            "flee_max_range_m, for flee_time_s, flees it: an evader, which breaks "
            "across the line of sight when the hunter closes in. It is held at flee_aim_point_m instead of "
            "aim_point_m, every sighting of it is followed (as follow_sighted_track), and once lost it is looked for "
            "after flee_search_after_s; 0: no target is an evader (the paper's)");
    c.param("flee_min_share", &C::flee_min_share)
        .range(0.0, 1.0)
        .describe("flee_min_speed_m_s: the least share of the target's speed directed away from the hunter");
    c.param("flee_max_range_m", &C::flee_max_range_m)
        .with_unit("m")
        .range(0.0, 1000.0)
        .describe("flee_min_speed_m_s: farther from the hunter, a target moving away is not fleeing it");
    c.param("flee_min_closing_m_s", &C::flee_min_closing_m_s)
        .with_unit("m/s")
        .range(0.0, 100.0)
        .describe("flee_min_speed_m_s: the hunter closes on the target at least this fast (it flees the hunter)");
    c.param("flee_time_s", &C::flee_time_s)
        .with_unit("s")
        .range(0.0, 60.0)
        .describe("flee_min_speed_m_s: how long it flees without a break before it is an evader");
    c.param("flee_aim_point_m", &C::flee_aim_point_m)
        .with_unit("m")
        .range(-50.0, 50.0)
        .describe(
            "flee_min_speed_m_s: x_E^d for an evader (camera frame): on the net's line, beyond where it opens, so "
            "that the evader only flees and the net, flying on while open, sweeps on to it");
    c.param("flee_search_after_s", &C::flee_search_after_s)
        .with_unit("s")
        .range(-1.0, 1000.0)
        .describe(
            "flee_min_speed_m_s: an evader lost, when_lost back_off turns to search this long after the back-off "
            "begins (it broke past the hunter, or fled behind it); < 0: as back_off_search_after_s");
    c.param("flee_fire_probability", &C::flee_fire_probability)
        .range(0.0, 1.0)
        .describe(
            "flee_min_speed_m_s: the least probability to fire at an evader (with fire_probability set), every net "
            "alike; 0: as any target. A run-in's chance keeps rising as it closes: waiting for a better one is cheap");
    c.param("flee_calm_speed_m_s", &C::flee_calm_speed_m_s)
        .with_unit("m/s")
        .range(0.0, 100.0)
        .describe(
            "flee_min_speed_m_s: an evader calms once the hunter is farther than flee_max_range_m; one faster than "
            "this for flee_calm_time_s (more than it is slower) flies its own path, and is no evader for the rest of "
            "the engagement (a figure-8 swinging along the line of sight can pass for one); 0: never checked");
    c.param("flee_calm_time_s", &C::flee_calm_time_s)
        .with_unit("s")
        .range(0.0, 100.0)
        .describe("flee_calm_speed_m_s: how long");
    c.param("flee_forget_s", &C::flee_forget_s)
        .with_unit("s")
        .range(0.0, 3600.0)
        .describe(
            "flee_min_speed_m_s: the target stays an evader through its estimate's restarts, until nothing has been "
            "seen for this long");
    c.choice("aim_tilt", &C::aim_tilt,
             {{"level", C::AimTilt::level}, {"target", C::AimTilt::target}, {"hunter", C::AimTilt::hunter}})
        .describe(
            "the camera's attitude the aim pose is computed for (the launcher tilts with it: at 6 m/s^2 of "
            "acceleration the net would open 1.3 m (forward) or 0.5 m (sideways) off a level pose): level (the "
            "paper's); tilted as the hunter is when it accelerates with aim_tilt_share of the target's estimated "
            "acceleration; or tilted as the hunter is now");
    c.param("aim_tilt_share", &C::aim_tilt_share)
        .range(0.0, 1.0)
        .describe("aim_tilt target: the share of the target's estimated acceleration the hunter is expected to fly");
    c.param("aim_tilt_time_s", &C::aim_tilt_time_s)
        .with_unit("s")
        .range(0.0, 100.0)
        .describe(
            "aim_tilt target: time constant of the low-pass the estimated acceleration goes through first (its "
            "noise would shake the aim pose by up to 2.3 m times the tilt it makes); 0: none");
    c.param("orbit_step_deg", &C::orbit_step_deg)
        .with_unit("deg")
        .range(0.0, 180.0)
        .describe(
            "with motion_axis_time_s: how far round the target, from the line of sight towards its axis of motion, "
            "the aim pose stands each frame (the hunter circles at the standoff, the camera on the target)");
    c.param("cooldown_s", &C::cooldown_s).with_unit("s").range(0.0, 3600.0).describe("least time between two shots");
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

  explicit AimPlannerNode(NodeInit& init)
      : cfg_(init.config<AimPlannerConfig>()),
        guidance_(init.make_component<guidance::Guidance>("guidance")),
        evader_guidance_(init.make_component<guidance::Guidance>("evader_guidance")),
        predictor_(init.make_component<guidance::Predictor>("predictor")),
        fire_policy_(init.make_component<FirePolicy>("fire_policy")) {
    if (cfg_.patrol_min_length_m > 0.0)
      patrol_.emplace(LinePatrolConfig{.window_s = cfg_.patrol_window_s,
                                       .min_length_m = cfg_.patrol_min_length_m,
                                       .max_residual_m = cfg_.patrol_max_residual_m});
  }

  void process(Context& ctx) override {
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
    std::optional<Eigen::Vector3d> error;
    std::optional<double> miss, probability, spread;
    std::optional<PredictedShot> shot;
    std::optional<ShotUncertainty> uncertainty;
    std::optional<double> capture_now;  // on the futures, when they are drawn
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
    if (target) {
      // The target is estimated again in the world frame, from what was seen of it there: its
      // velocity in the camera frame would include the hunter's own motion, and feeding that
      // forward would chase the hunter's tail. The track's detection, not its filtered state: a
      // filter in the camera frame lags whenever the camera turns.
      const Eigen::Vector3d in_camera = target->detection.allFinite() ? target->detection : target->position();
      const Eigen::Vector3d intruder = camera.to_world(in_camera);
      if (!first_seen_range_) first_seen_range_ = in_camera.norm();
      // A new track id is often the same intruder, its track restarted after a few misses: the
      // estimate goes on (and keeps what it knows of the velocity) when the sighting is where it
      // predicts, or where the oscillation does, within reacquire_m; a new estimate otherwise.
      const bool same_target = estimate_ && (target->id == target_id_ || expected_near(t, intruder));
      target_id_ = target->id;
      if (!same_target) {
        estimate_.emplace(
            intruder, TargetFilterConfig{cfg_.target_filter, cfg_.target_q, cfg_.target_q_velocity, cfg_.target_q_turn,
                                         cfg_.target_switch_probability, cfg_.target_r});
        if (cfg_.shot_prediction == AimPlannerConfig::ShotPrediction::oscillation)
          oscillation_.emplace(OscillationConfig{cfg_.oscillation_window_s, cfg_.oscillation_min_omega_rad_s,
                                                 cfg_.oscillation_max_omega_rad_s, cfg_.oscillation_min_improvement});
        estimate_since_ = t;
        guidance_->reset();
        evader_guidance_->reset();
        motion_axis_.reset();
        tilt_acceleration_.setZero();
      } else {
        estimate_->update(intruder);
      }
      if (oscillation_) oscillation_->add(t, intruder);
      // The futures only where a component reads them: each frame's draw costs about a millisecond.
      if (guidance_->needs_futures() || evader_guidance_->needs_futures() || fire_policy_->needs_futures())
        futures_ = predictor_->predict(estimate_->hypotheses());
      const Eigen::VectorXd x = estimate_->state();
      // A patrol flies its own line, away from the hunter waiting at its end as often as towards it.
      if (cfg_.flee_min_speed_m_s > 0.0 && !patrol_found()) {
        flee_.update(dt, x.head<3>(), x.segment<3>(3), hunter->position, hunter->velocity);
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
      goal_ = aim_pose(aimed.position, hunter->position, geometry::yaw_of(hunter->orientation),
                       guidance::AimGeometry{aim_point(), cfg_.camera_offset_m},
                       expected_acceleration(*hunter, aimed.waiting));
      if (cfg_.motion_axis_time_s > 0.0) stand_along_motion(x, dt);
      if (patrol_) {
        watch_patrol(t, intruder);
        if (const auto lookout = patrol_pose(*hunter)) {
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
      error = aim_point() - in_camera;
      ++target_frames_;
      squared_error_ += error->squaredNorm();
      // The net leaves when the order reaches the launcher, not at the capture the tracks come
      // from: in realtime the perception chain's latency (now - capture) and the link's
      // (fire_latency_s) pass first, the hunter and the target moving on meanwhile.
      const double lead = std::max(0.0, to_seconds(ctx.now()) - t) + cfg_.fire_latency_s;
      geometry::CameraPose launch = camera;
      launch.position_world += hunter->velocity * lead;
      shot = predict_target_shot(launch, hunter->velocity, x, lead);
      miss = shot->miss.norm();
      // The estimate's position uncertainty, grown over the time the net takes to its closest
      // approach: how far it can be trusted, and the chance the net holds the target.
      const Eigen::Matrix3d ahead = estimate_->position_covariance_after(shot->time_s);
      spread = std::sqrt(std::max(0.0, Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(ahead).eigenvalues().maxCoeff()));
      uncertainty = ShotUncertainty{cfg_.shot_covariance_scale * estimate_->covariance().topLeftCorner<6, 6>(), lead,
                                    expected_shot_acceleration(x),
                                    cfg_.shot_manoeuvre_m_s2 + cfg_.shot_turn_rate_rad_s * x.segment<3>(3).norm()};
      // Every frame only when it decides the shot; otherwise once, for the shot's record.
      if (cfg_.fire_probability > 0.0) probability = hit_probability(*shot, *uncertainty, cfg_.net_radius_m);
      // The same launch counted on the futures (from the estimate's time: the launch is `lead` later).
      if (!futures_.empty())
        capture_now =
            guidance::capture_chance(futures_, open_net_, guidance::Launch{lead, launch, hunter->velocity}).probability;
    }

    if (goal_ && target) {
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
    } else if (const auto lookout = patrol_ && patrol_waiting(t) ? patrol_pose(*hunter) : std::nullopt) {
      // Out of sight at the patrol's far end: it comes back to the end the hunter waits at.
      ++patrol_frames_;
      reference_->advance(*lookout, Eigen::Vector3d::Zero(), dt);
    } else if (goal_ && t - last_seen_ <= cfg_.target_timeout_s) {
      // A short loss: on towards the last aim pose, without feeding forward a velocity nobody sees.
      reference_->advance(*goal_, Eigen::Vector3d::Zero(), dt);
    } else if (goal_) {
      if (!holding_) {
        ++holds_;
        standoff_ = back_off_pose(*hunter);
        search_turn_ = search_side(reference_->yaw(), hunter->position,
                                   expected_position(last_target_, last_target_velocity_, t - last_seen_));
      }
      holding_ = true;
      using L = AimPlannerConfig::WhenLost;
      const bool searching =
          cfg_.when_lost == L::search || (cfg_.when_lost == L::back_off && search_after_s() >= 0.0 &&
                                          t - last_seen_ >= cfg_.target_timeout_s + search_after_s());
      if (searching) {
        ++search_frames_;
        reference_->hold(dt, search_turn_ * cfg_.search_yaw_rate_deg_s * M_PI / 180.0);
      } else if (cfg_.when_lost == L::back_off) {
        reference_->advance(standoff_, Eigen::Vector3d::Zero(), dt);
      } else {
        reference_->hold(dt, 0.0);
      }
    } else {
      // No target yet: climb, then look ahead (once at the take-off height: a hunter on the ground
      // goes up before it goes forward).
      reference_->advance(armed_ ? search_ : takeoff_, Eigen::Vector3d::Zero(), dt);
    }
    if (target)
      holding_ = false;
    else
      later_value_.reset();

    msg::TrajectorySetpoint sp;
    sp.stamp = tracks->stamp;
    sp.position = reference_->position();
    sp.velocity = reference_->velocity();
    sp.acceleration = reference_->acceleration();
    sp.yaw = reference_->yaw();
    sp.yaw_rate = reference_->yaw_rate();
    ctx.publish(kSetpoint, std::move(sp));

    const bool trusted = spread && (cfg_.max_shot_spread_m <= 0.0 || *spread <= cfg_.max_shot_spread_m);
    const auto launcher = ctx.get(kLauncher);
    const FireChances chances{worth_a_net(ctx, miss, probability), capture_now.value_or(0.0), later_value_,
                              launcher ? static_cast<int>(launcher->nets_left) : -1};
    if (fire_.decide(t, launcher_ready(ctx, t) && trusted && target && fire_policy_->worth_a_net(chances))) {
      ++fire_count_;
      if (!first_fire_) first_fire_ = t;
      if (!probability) probability = hit_probability(*shot, *uncertainty, cfg_.net_radius_m);
      ctx.log().info("fire at t = {:.2f} s: target {}, aim error {:.2f} m, predicted miss {:.2f} m{}", t, target->id,
                     error->norm(), *miss,
                     probability ? fmt::format(", probability {:.2f}", *probability) : std::string());
      nlohmann::json record{{"t_s", t},
                            {"predicted_miss_m", *miss},
                            {"probability", probability ? nlohmann::json(*probability) : nlohmann::json()},
                            {"spread_m", *spread},
                            {"capture_now", capture_now ? nlohmann::json(*capture_now) : nlohmann::json()},
                            {"later_value", later_value_ ? nlohmann::json(*later_value_) : nlohmann::json()},
                            {"predicted_time_s", shot->time_s},
                            {"estimate_age_s", t - estimate_since_},
                            {"prediction", prediction_record(*shot, uncertainty->lead_s, *estimate_, oscillation_)}};
      if (const auto mu = estimate_->model_probabilities(); !mu.empty()) record["model_probabilities"] = mu;
      shots_.push_back(std::move(record));
      ctx.publish(kFire, msg::NetFire{tracks->stamp, target->id, *error});
    }
  }

  // The miss if the net were fired now, on the launcher's ballistics, against the target predicted
  // over the time the net is open (shot_prediction: at constant velocity by default; the
  // estimate's acceleration, extrapolated that far, is noisier at low speeds).
  // `lead`: seconds from the estimate's time to the launch.
  PredictedShot predict_target_shot(const geometry::CameraPose& camera, const Eigen::Vector3d& hunter_velocity,
                                    const Eigen::VectorXd& x, double lead) const {
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
  static nlohmann::json prediction_record(const PredictedShot& shot, double lead_s, const TargetEstimate& estimate,
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
  Eigen::Vector3d expected_shot_acceleration(const Eigen::VectorXd& x) const {
    if (patrolling_) return Eigen::Vector3d::Zero();  // the patrol's prediction brakes already
    Eigen::Vector3d a = cfg_.shot_acceleration_share * x.segment<3>(6);
    if (oscillation_)
      for (int axis = 0; axis < 3; ++axis)
        if (oscillation_->axes()[axis]) a[axis] = 0.0;
    return a;
  }

  // The hunter's acceleration while it holds the aim (aim_tilt), which tilts its camera: the
  // target's, which a hunter riding along with it flies; or the one its attitude holds now, the
  // thrust's horizontal part over its vertical part carrying the weight.
  // A hunter waiting at a swing's centre flies none of the target's acceleration along that axis.
  Eigen::Vector3d expected_acceleration(const msg::VehicleState& hunter, const std::array<bool, 3>& waiting) const {
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
  bool expected_near(double t, const Eigen::Vector3d& sighting) const {
    const Eigen::Vector3d predicted = estimate_->state().head<3>();
    if ((predicted - sighting).norm() <= cfg_.reacquire_m) return true;
    // last_seen_: the newest sighting, the oscillation's too.
    return oscillation_ && (oscillation_->predict(t - last_seen_, predicted) - sighting).norm() <= cfg_.reacquire_m;
  }

  // What the hunter flies of an acceleration: its horizontal part within max_acceleration_m_s2,
  // its thrust within max_tilt_deg, as the aim's reference limits it. A target that turns harder
  // than the hunter can is aimed at from the tilt the hunter reaches, not one it never reaches.
  Eigen::Vector3d flyable(Eigen::Vector3d acceleration) const {
    const double horizontal = acceleration.head<2>().norm();
    if (horizontal > cfg_.max_acceleration_m_s2) acceleration.head<2>() *= cfg_.max_acceleration_m_s2 / horizontal;
    return vehicle::tilt_limited_acceleration(acceleration, max_tilt_rad(), guidance::kGravity_m_s2);
  }

  bool patrol_found() const { return patrol_ && patrol_->line(); }
  // Whether the target is an evader: seen fleeing the hunter, and flying no patrol.
  bool evader() const { return flee_.fleeing() && !patrol_found(); }

  // x_E^d: farther for an evader (flee_aim_point_m), outside the radius where it breaks.
  const Eigen::Vector3d& aim_point() const { return evader() ? cfg_.flee_aim_point_m : cfg_.aim_point_m; }

  // When the back-off turns to search: sooner for an evader, which broke past or fled behind.
  double search_after_s() const {
    return evader() && cfg_.flee_search_after_s >= 0.0 ? cfg_.flee_search_after_s : cfg_.back_off_search_after_s;
  }

  double max_tilt_rad() const { return cfg_.max_tilt_deg * std::numbers::pi / 180.0; }

  // The launcher (when connected) fires only when loaded and not reloading.
  static bool launcher_ready(Context& ctx, double t) {
    const auto launcher = ctx.get(kLauncher);
    return !launcher || (launcher->nets_left != 0 && t >= to_seconds(launcher->ready_at));
  }

  // Whether this shot is worth a net: by probability when fire_probability is set, else by the
  // predicted miss; the last net waits for a better shot than the others.
  bool worth_a_net(Context& ctx, std::optional<double> miss, std::optional<double> probability) const {
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

  void finish(Context& ctx) override {
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

 private:
  void start(const msg::VehicleState& hunter) {
    AimReference::Limits limits{cfg_.gain_1_s, cfg_.max_speed_m_s, cfg_.max_acceleration_m_s2,
                                cfg_.max_yaw_rate_deg_s * M_PI / 180.0, max_tilt_rad()};
    reference_.emplace(limits, hunter.position, geometry::yaw_of(hunter.orientation));
    takeoff_.position = hunter.position;
    takeoff_.position.z() = std::max(hunter.position.z(), cfg_.takeoff_altitude_m);
    takeoff_.yaw = geometry::yaw_of(hunter.orientation);
    search_ = takeoff_;
    search_.position += cfg_.search_advance_m * Eigen::Vector3d(std::cos(takeoff_.yaw), std::sin(takeoff_.yaw), 0.0);
  }

  // What the guidance law sees: the reference it steers, the target's estimate, the aim pose.
  guidance::Engagement engagement(double dt) const {
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
    return e;
  }

  // The aim pose moved round the target towards its axis of motion (motion_axis.hpp), the heading
  // still on the target: the camera keeps it in view while the hunter circles.
  void stand_along_motion(const Eigen::VectorXd& x, double dt) {
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
  void watch_patrol(double t, const Eigen::Vector3d& sighting) {
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
  bool patrol_waiting(double t) const {
    const auto last = patrol_->last_sighting_s();
    return patrol_->line() && last && t - *last <= cfg_.patrol_timeout_s;
  }

  // The aim pose that waits beyond an end of the patrol where the target turned (the one chosen
  // before, else the nearest), facing along the line, the end at x_E^d.
  std::optional<AimPose> patrol_pose(const msg::VehicleState& hunter) {
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

  // Back off from where the target was last seen, along the line to the hunter, and face it: from
  // farther away the camera sees more, above and below as well as to the sides.
  AimPose back_off_pose(const msg::VehicleState& hunter) const {
    Eigen::Vector2d away = (hunter.position - last_target_).head<2>();
    if (away.norm() < 1e-3) away = -Eigen::Vector2d(std::cos(reference_->yaw()), std::sin(reference_->yaw()));
    away.normalize();
    AimPose pose;
    pose.position.head<2>() = last_target_.head<2>() + cfg_.back_off_distance_m * away;
    pose.position.z() = std::max(cfg_.min_altitude_m, last_target_.z() + cfg_.back_off_height_m);
    pose.yaw = std::atan2(-away.y(), -away.x());
    return pose;
  }

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
  guidance::TargetFutures futures_;    // this frame's, from the estimate's time
  std::optional<double> later_value_;  // the planner's best later launch, discounted
  AimPose takeoff_, search_, standoff_;
  Eigen::Vector3d last_target_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d last_target_velocity_ = Eigen::Vector3d::Zero();
  double search_turn_ = 1.0;  // +1 counter-clockwise, -1 clockwise: where the lost target went (search_side)
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
KESTREL_REGISTER_NODE(AimPlannerNode)

}  // namespace kestrel::aim
