#include "statistics.hpp"

#include <boost/math/distributions/students_t.hpp>
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
  // Boost would throw on a domain error; no spread to measure is "no interval" here.
  if (!(df > 0) || !(p > 0 && p < 1)) return std::numeric_limits<double>::quiet_NaN();
  return boost::math::quantile(boost::math::students_t_distribution<double>(df), p);
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
