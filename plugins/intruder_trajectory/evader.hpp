#pragma once
// An intruder that sees its hunter and evades it, as a multirotor can: its acceleration and speed
// are bounded, so it never reverses at once. It cruises between random waypoints in its box; when
// the hunter comes within `flee_radius`, it flees at top speed away from the hunter, weaving
// across its path; when the hunter closes within `break_radius`, it breaks hard across the
// hunter's line of sight, to the side it is already moving, and climbs or dives. Leaving its box,
// it is steered back in (a cornered intruder is easier to catch, as a real one is).
// Integrated on a 10 ms grid from a seed, so that a run in lockstep reproduces.
#include <Eigen/Core>
#include <optional>
#include <random>

#include "trajectory.hpp"

namespace kestrel::intruder {

struct EvaderParams {
  Eigen::Vector3d centre{8.0, 0.0, 3.0};       ///< its box's centre (world, m)
  Eigen::Vector3d half_extent{3.0, 4.0, 1.0};  ///< its box's half size (m)
  double cruise_speed = 2.0;                   ///< m/s, between waypoints
  double top_speed = 6.0;                      ///< m/s, fleeing and breaking
  double max_acceleration = 6.0;               ///< m/s^2
  double flee_radius = 6.0;                    ///< m: the hunter this close, it flees
  double break_radius = 2.5;                   ///< m: this close, it breaks
  double weave_period = 1.5;                   ///< s: one weave left and right while fleeing
  double min_height = 1.0;                     ///< m: never lower (world z)
};

class Evader {
 public:
  Evader(const Eigen::Vector3d& start, const EvaderParams& params, std::uint64_t seed);
  /// Flies on to time t (never backwards) against the hunter's position, if it is known.
  State step(double t, const std::optional<Eigen::Vector3d>& hunter);
  enum class Mode { cruise, flee, break_away };
  Mode mode() const { return mode_; }

 private:
  Eigen::Vector3d desired_velocity(const std::optional<Eigen::Vector3d>& hunter);
  Eigen::Vector3d back_into_box(const Eigen::Vector3d& desired) const;

  EvaderParams p_;
  std::mt19937_64 rng_;
  State state_;
  double t_ = 0.0;
  Mode mode_ = Mode::cruise;
  Eigen::Vector3d waypoint_;
  double break_side_ = 1.0, break_climb_ = 0.0;  // the break's direction, chosen as it starts
};

}  // namespace kestrel::intruder
