#pragma once
// A target that repeats itself, as one more hypothesis of its futures: a drone that loiters,
// patrols or circles comes back through states it has flown before, and what followed them then is
// a forecast of what follows now (the method of analogues). The target's own estimate is kept for
// `window_s`; the past states nearest the present one (position within about `position_m`, velocity
// within about `velocity_m_s`), whose next `horizon` seconds are known, each give a path: the
// displacement it flew then, from where the target is now. Its weight is how well it has foretold
// the sightings: each sighting is compared with where the analogues and the motion models put it
// `check_s` before, and the log odds sum the likelihood ratio. A target that never repeats itself
// finds no analogue, or one that foretells worse, and the hypothesis fades. Nothing in it knows a
// kind of flight.
#include <Eigen/Core>
#include <deque>
#include <optional>
#include <vector>

#include "kestrel/guidance/log_odds.hpp"

namespace kestrel::guidance {

struct RepeatConfig {
  double prior = 0.5;            ///< its weight before any evidence (0: no such hypothesis)
  double window_s = 20.0;        ///< how much of the target's past is searched
  std::int64_t matches = 4;      ///< the analogues used, nearest first
  double position_m = 0.7;       ///< the scale of a position match
  double velocity_m_s = 1.0;     ///< the scale of a velocity match
  double max_distance = 1.0;     ///< no analogue farther than this, in those scales (root of the summed squares)
  double check_s = 1.0;          ///< how far ahead its forecasts are checked against the sightings
  double error_m = 0.5;          ///< the forecasts' error scale for that check
  double evidence_time_s = 0.5;  ///< this long of sightings counts as one observation
  double max_probability = 0.9;  ///< neither hypothesis is ever surer than this
};

class RepeatPredictor {
 public:
  explicit RepeatPredictor(RepeatConfig config = {});
  /// One frame of the estimate, dt after the last (world).
  void observe(double dt, const Eigen::Vector3d& position, const Eigen::Vector3d& velocity);
  /// Paths of `steps` steps of `step_s` from now, one per analogue (none: no analogue, or the
  /// hypothesis is off). `models_ahead`: where the motion models put the target `check_s` ahead
  /// (kept to weigh the hypothesis against them).
  std::vector<Eigen::Matrix3Xd> paths(Eigen::Index steps, double step_s, const Eigen::Vector3d& models_ahead);
  double probability() const;
  const RepeatConfig& config() const { return cfg_; }

 private:
  struct Past {
    double t;
    Eigen::Vector3d position, velocity;
  };
  struct Forecast {
    double t;                               ///< when it was made
    std::optional<Eigen::Vector3d> repeat;  ///< the analogues' mean check_s ahead
    Eigen::Vector3d models;                 ///< the motion models' mean check_s ahead
  };
  /// The position at time t, linear between the kept states (t within the window).
  Eigen::Vector3d position_at(double t) const;

  RepeatConfig cfg_;
  std::deque<Past> past_;
  std::deque<Forecast> forecasts_;
  double now_ = 0.0;
  HypothesisWeight weight_{cfg_.prior, cfg_.max_probability};
};

}  // namespace kestrel::guidance
