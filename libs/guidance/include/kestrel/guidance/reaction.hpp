#pragma once
// A target that reacts to the hunter, as one more hypothesis of its futures: within `radius_m` of
// the hunter it flies away from it, its velocity turning straight away at its own speed (at least
// `speed_m_s`) within `acceleration_m_s2` (a multirotor's response, `response_s`). Its weight is how well it explains
// the sightings: each frame the hunter is within the radius, the direction the target moves is
// scored under both hypotheses (it reacts: away from the hunter, concentrated about that direction;
// it does not: any direction alike), the log odds of reacting summing their likelihood ratio and
// slowly forgetting it. A target slower than `speed_m_s` counts as moving that much less away. Nothing in it is keyed
// to a path the target flies: a target that never comes near the hunter never shows either way.
#include <Eigen/Core>
#include <cstddef>
#include <functional>

#include "kestrel/guidance/log_odds.hpp"

namespace kestrel::guidance {

struct TargetFutures;

struct ReactionConfig {
  double prior = 0.0;              ///< the reacting hypothesis's weight before any evidence (0: none)
  double radius_m = 5.0;           ///< it reacts to a hunter this near
  double speed_m_s = 2.0;          ///< it flees at its own speed, at least this
  double acceleration_m_s2 = 6.0;  ///< and accelerates no harder
  double response_s = 0.25;        ///< its velocity's time constant towards the flight away
  double concentration = 3.0;      ///< how tightly a reacting target's motion points away
  double evidence_time_s = 0.5;    ///< the evidence of this long counts as one observation
  double memory_s = 10.0;          ///< the log odds forget towards the prior with this time constant
  double max_probability = 0.98;   ///< nor is either hypothesis ever sure
};

/// Where the hunter will be at time s from the futures' origin (world).
using HunterPath = std::function<Eigen::Vector3d(double)>;

/// The acceleration of a reacting target at `position`, moving at `velocity`, with the hunter at
/// `hunter`: zero beyond the radius.
Eigen::Vector3d reaction_acceleration(const ReactionConfig& config, const Eigen::Vector3d& position,
                                      const Eigen::Vector3d& velocity, const Eigen::Vector3d& hunter);

/// The weight of the reacting hypothesis, learnt from the sightings.
class ReactionBelief {
 public:
  explicit ReactionBelief(ReactionConfig config = {});
  /// One frame of the world estimate: the target's position and velocity; where the hunter is.
  void observe(double dt, const Eigen::Vector3d& position, const Eigen::Vector3d& velocity,
               const Eigen::Vector3d& hunter);
  double probability() const;
  void reset();
  const ReactionConfig& config() const { return cfg_; }

 private:
  ReactionConfig cfg_;
  HypothesisWeight weight_{cfg_.prior, cfg_.max_probability};
};

/// The futures as they would be if every path reacted to a hunter flying `hunter`: each path of
/// every `stride`th starts from its own state and follows its own motion beyond the radius, but
/// flees within it. The same time grid as `futures`.
TargetFutures reacting_futures(const TargetFutures& futures, const ReactionConfig& config, const HunterPath& hunter,
                               std::size_t stride = 4);

}  // namespace kestrel::guidance
