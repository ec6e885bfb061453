#include "kestrel/algorithms/lag.hpp"

#include <algorithm>
#include <cmath>

namespace kestrel::algorithms {

Eigen::Vector3d interpolate(const std::vector<TimedPoint>& truth, double t) {
  if (truth.empty()) return Eigen::Vector3d::Zero();
  if (t <= truth.front().t) return truth.front().p;
  if (t >= truth.back().t) return truth.back().p;
  const auto hi =
      std::upper_bound(truth.begin(), truth.end(), t, [](double v, const TimedPoint& s) { return v < s.t; });
  const auto lo = hi - 1;
  const double f = (t - lo->t) / (hi->t - lo->t);
  return lo->p + f * (hi->p - lo->p);
}

std::optional<double> estimate_lag(const std::vector<TimedPoint>& truth, const std::vector<TimedPoint>& measured,
                                   double max_lag, double step) {
  if (truth.size() < 2 || measured.size() < 3 || step <= 0) return std::nullopt;
  double best = -2.0;
  std::optional<double> best_lag;
  const int steps = static_cast<int>(std::floor(max_lag / step + 1e-9));
  for (int k = -steps; k <= steps; ++k) {
    const double s = k * step;
    // Only pairs where the shifted truth exists: no extrapolation.
    std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> pairs;
    for (const auto& m : measured) {
      const double t = m.t - s;
      if (t < truth.front().t || t > truth.back().t) continue;
      pairs.emplace_back(interpolate(truth, t), m.p);
    }
    if (pairs.size() < 3) continue;
    Eigen::Vector3d mean_a = Eigen::Vector3d::Zero(), mean_b = Eigen::Vector3d::Zero();
    for (const auto& [a, b] : pairs) {
      mean_a += a;
      mean_b += b;
    }
    mean_a /= static_cast<double>(pairs.size());
    mean_b /= static_cast<double>(pairs.size());
    double cov = 0, var_a = 0, var_b = 0;
    for (const auto& [a, b] : pairs) {
      cov += (a - mean_a).dot(b - mean_b);
      var_a += (a - mean_a).squaredNorm();
      var_b += (b - mean_b).squaredNorm();
    }
    if (var_a <= 1e-12 || var_b <= 1e-12) continue;
    const double r = cov / std::sqrt(var_a * var_b);
    // Ties go to the smallest |lag|: scanning outward would be equivalent; keep the first strict max.
    if (r > best + 1e-12 || (std::abs(r - best) <= 1e-12 && best_lag && std::abs(s) < std::abs(*best_lag))) {
      best = r;
      best_lag = s;
    }
  }
  return best_lag;
}

}  // namespace kestrel::algorithms
