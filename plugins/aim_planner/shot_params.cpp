// The aim planner's firing parameters: the predicted miss, the shot's probability, the net, the dwell.
#include "aim_planner_config.hpp"

namespace kestrel::aim {

void declare_shot_params(AimConfigSpec& c) {
  using C = AimPlannerConfig;
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
  c.param("dwell_s", &C::dwell_s).with_unit("s").range(0.0, 60.0).describe("how long the aim must hold before firing");
  c.param("cooldown_s", &C::cooldown_s).with_unit("s").range(0.0, 3600.0).describe("least time between two shots");
}

}  // namespace kestrel::aim
