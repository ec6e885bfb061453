#pragma once
// Time lag between two sampled 3D curves by cross-correlation, as in the paper's section 3.2:
// the shift that maximises the correlation coefficient between a true curve and a measured one.
#include <Eigen/Core>
#include <optional>
#include <vector>

namespace kestrel::algorithms {

struct TimedPoint {
  double t = 0.0;
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
};

/// The lag s in [-max_lag, max_lag] (searched in steps of `step`) that maximises the correlation
/// between measured(t) and truth(t - s): a positive lag means the measurement trails the truth.
/// Truth is interpolated linearly; the coefficient pools the axes (axes that do not move add
/// nothing). Returns nullopt if the curves overlap too little or do not move.
std::optional<double> estimate_lag(const std::vector<TimedPoint>& truth, const std::vector<TimedPoint>& measured,
                                   double max_lag = 1.0, double step = 0.001);

/// truth at time t by linear interpolation (clamped at the ends); truth sorted by time.
Eigen::Vector3d interpolate(const std::vector<TimedPoint>& truth, double t);

}  // namespace kestrel::algorithms
