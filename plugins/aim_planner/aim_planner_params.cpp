// The aim planner's flight parameters: limits, where the target is held, its estimate, the aim's tilt.
#include <kestrel/vehicle/airframe.hpp>

#include "aim_planner_config.hpp"

namespace kestrel::aim {

void declare_flight_params(AimConfigSpec& c) {
  using C = AimPlannerConfig;
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
  c.param("motion_axis_time_s", &C::motion_axis_time_s)
      .with_unit("s")
      .range(0.0, 100.0)
      .describe(
          "stand on the target's axis of motion (the principal direction of its horizontal velocity, averaged over "
          "this long), so that the net sweeps along its path and only its manoeuvre across it counts against the "
          "net's radius; 0: stand on the line of sight, where the hunter happens to be (the paper's)");
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
}

}  // namespace kestrel::aim
