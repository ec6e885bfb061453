#pragma once
// A hypothesis's weight as log odds, in which the hypotheses of the target's futures
// (reaction.hpp, repeat_prediction.hpp) sum the evidence of the sightings.
#include <algorithm>
#include <cmath>

namespace kestrel::guidance {

inline double logit(double p) { return std::log(p / (1.0 - p)); }
inline double logistic(double log_odds) { return 1.0 / (1.0 + std::exp(-log_odds)); }

/// Starts at its prior and sums the evidence (log likelihood ratios), never surer than `most`
/// either way. A prior of 0 is no hypothesis at all: its weight stays 0.
class HypothesisWeight {
 public:
  HypothesisWeight(double prior, double most) : active_(prior > 0.0), most_(logit(most)) {
    prior_ = active_ ? logit(std::clamp(prior, 1.0 - most, most)) : 0.0;
    log_odds_ = prior_;
  }
  bool active() const { return active_; }
  double probability() const { return active_ ? logistic(log_odds_) : 0.0; }
  void add(double evidence) { log_odds_ = std::clamp(log_odds_ + evidence, -most_, most_); }
  /// What was learnt fades towards the prior: `keep` of it is kept.
  void fade(double keep) { log_odds_ = prior_ + (log_odds_ - prior_) * keep; }
  void reset() { log_odds_ = prior_; }

 private:
  bool active_;
  double most_, prior_ = 0.0, log_odds_ = 0.0;
};

}  // namespace kestrel::guidance
