#pragma once
// Log odds, in which the hypotheses of the target's futures (reaction.hpp, repeat_prediction.hpp)
// sum the evidence of the sightings.
#include <cmath>

namespace kestrel::guidance {

inline double logit(double p) { return std::log(p / (1.0 - p)); }
inline double logistic(double log_odds) { return 1.0 / (1.0 + std::exp(-log_odds)); }

}  // namespace kestrel::guidance
