#pragma once
// The aim planner's parameters, one struct the node's spec binds. They are declared in three
// groups: how the hunter flies and estimates the target (aim_planner_params.cpp), when it fires
// (shot_params.cpp), and the recognisers of particular flights (recogniser_params.cpp), which the
// planner over the target's futures is to replace.
#include <Eigen/Core>
#include <string>

#include "kestrel/component.hpp"
#include "kestrel/config_spec.hpp"
#include "target_estimate.hpp"

namespace kestrel::aim {

struct AimPlannerConfig {
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
  ComponentConfig search;
};

using AimConfigSpec = ConfigSpec<AimPlannerConfig>;

/// How the hunter flies, where it holds the target and how it estimates it.
void declare_flight_params(AimConfigSpec& c);
/// When the aim fires: the predicted miss or the shot's probability, the net, the dwell.
void declare_shot_params(AimConfigSpec& c);
/// The recognisers of particular flights: oscillation, swing centre, line patrol, flee watch.
void declare_recogniser_params(AimConfigSpec& c);

}  // namespace kestrel::aim
