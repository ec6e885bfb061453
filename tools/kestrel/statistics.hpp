#pragma once
// The statistics of `kestrel ab`: means, and the paired difference of two samples with its 95%
// confidence interval (Student's t). Pairing by seed removes the scenario's own variation.
#include <cstddef>
#include <vector>

namespace kestrel::cli {

/// The mean of the values; NaN for none.
double mean(const std::vector<double>& values);

/// The sample standard deviation (n - 1 in the denominator); 0 for fewer than two values.
double sample_sd(const std::vector<double>& values);

/// The quantile of Student's t distribution with `df` degrees of freedom at probability p.
double t_quantile(double p, double df);

struct Interval {
  double low = 0.0, high = 0.0;
  bool contains(double x) const { return low <= x && x <= high; }
};

/// Pairs (a[i], b[i]) measured under the same conditions (one seed), compared by b - a.
struct PairedDifference {
  std::size_t n = 0;
  double mean_a = 0.0, mean_b = 0.0;
  double mean_difference = 0.0;  ///< mean of b[i] - a[i]
  double sd_difference = 0.0;    ///< sample standard deviation of b[i] - a[i]
  Interval ci95;                 ///< of the mean difference; NaN bounds for fewer than two pairs
};

/// a and b must have the same length.
PairedDifference paired_difference(const std::vector<double>& a, const std::vector<double>& b);

}  // namespace kestrel::cli
