#include "statistics.hpp"

#include <cmath>
#include <limits>
#include <numeric>

#include "kestrel/error.hpp"

namespace kestrel::cli {

double mean(const std::vector<double>& values) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  return std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
}

double sample_sd(const std::vector<double>& values) {
  if (values.size() < 2) return 0.0;
  const double m = mean(values);
  double sum = 0.0;
  for (const double v : values) sum += (v - m) * (v - m);
  return std::sqrt(sum / static_cast<double>(values.size() - 1));
}

double t_quantile(double p, double df) {
  static const double table[] = {0,     12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228,
                                 2.201, 2.179,  2.160, 2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086, 2.080,
                                 2.074, 2.069,  2.064, 2.060, 2.056, 2.052, 2.048, 2.045, 2.042};
  if (p != 0.975) throw Error("only the 97.5% quantile of Student's t is tabulated");
  const int n = static_cast<int>(df);
  if (n <= 0) return std::numeric_limits<double>::quiet_NaN();
  return n <= 30 ? table[n] : 1.96 + 2.4 / n;  // close to the exact values beyond 30
}

PairedDifference paired_difference(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) throw Error("paired samples of different lengths");
  PairedDifference r;
  r.n = a.size();
  std::vector<double> d(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) d[i] = b[i] - a[i];
  r.mean_a = mean(a);
  r.mean_b = mean(b);
  r.mean_difference = mean(d);
  r.sd_difference = sample_sd(d);
  const double half =
      t_quantile(0.975, static_cast<double>(r.n) - 1) * r.sd_difference / std::sqrt(static_cast<double>(r.n));
  r.ci95 = {r.mean_difference - half, r.mean_difference + half};
  return r;
}

}  // namespace kestrel::cli
