// The parameters of the aim's recognisers of particular flights (oscillation, swing centre, line patrol,
// flee watch): to be replaced by the planner over the target's futures.
#include "aim_planner_config.hpp"

namespace kestrel::aim {

void declare_recogniser_params(AimConfigSpec& c) {
  using C = AimPlannerConfig;
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
          "the camera's range at the far end) before it searches as `search` says");
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
          "flee_min_speed_m_s: an evader lost, search back_off turns this long into the loss (it broke past the "
          "hunter, or fled behind it); < 0: as the search's own turn_after_s");
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
}

}  // namespace kestrel::aim
