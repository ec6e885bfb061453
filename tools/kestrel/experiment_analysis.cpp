#include "experiment_analysis.hpp"

#include <cmath>
#include <map>
#include <optional>

namespace kestrel::cli {

namespace {

std::vector<double> magnitudes(std::vector<double> values) {
  for (double& v : values) v = std::abs(v);
  return values;
}

// A verdict needs a direction from metrics_meta and an interval that excludes zero.
std::string verdict(const PairedDifference& d, int direction) {
  if (d.sd_difference == 0 && d.mean_difference == 0) return "equal";
  if (direction == 0) return "";
  if (d.ci95.contains(0) || std::isnan(d.ci95.low)) return "no significant difference";
  return (d.mean_difference > 0) == (direction > 0) ? "B" : "A";
}

}  // namespace

SweepSummary summarise_sweep(const SweepPlan& plan, const std::vector<BatchResult>& results) {
  SweepSummary s;
  for (const auto& r : results) {
    s.runs.push_back(report_metrics(r.report));
    s.exit_codes.push_back(r.exit_code);
    s.meta.add(r.report);
    for (const auto& [k, _] : s.runs.back()) s.metric_names.insert(k);
    if (r.exit_code != 0) ++s.failed;
  }
  s.means.resize(plan.grid.size());
  s.undefined.resize(plan.grid.size());
  s.runs_per_point.assign(plan.grid.size(), 0);
  for (std::size_t j = 0; j < s.runs.size(); ++j) ++s.runs_per_point[plan.point_of(j)];
  std::vector<Metrics> judged(plan.grid.size());  // means of what is judged: magnitudes where meta says so
  for (std::size_t g = 0; g < plan.grid.size(); ++g)
    for (const auto& m : s.metric_names) {
      std::vector<double> values;
      for (std::size_t j = 0; j < s.runs.size(); ++j)
        if (plan.point_of(j) == g)
          if (const auto it = s.runs[j].find(m); it != s.runs[j].end()) {
            if (std::isnan(it->second))
              ++s.undefined[g][m];
            else
              values.push_back(it->second);
          }
      s.means[g][m] = mean(values);
      judged[g][m] = s.meta.by_magnitude(m) ? mean(magnitudes(values)) : s.means[g][m];
    }
  for (const auto& m : s.metric_names)
    for (std::size_t g = 1; g < plan.grid.size(); ++g)
      if (!(s.means[g][m] == s.means[0][m])) s.varying.insert(m);  // NaN (missing) differs too
  for (const auto& m : s.metric_names) {
    const int direction = s.meta.direction(m);
    if (direction == 0) continue;
    std::optional<SweepSummary::Best> best;
    bool differ = false;
    for (std::size_t g = 0; g < plan.grid.size(); ++g) {
      const double v = judged[g][m];
      if (std::isnan(v)) continue;
      if (best && v != best->value) differ = true;
      if (!best || direction * v > direction * best->value)
        best = SweepSummary::Best{g, v, 0};
      else if (v == best->value)
        ++best->ties;
    }
    if (best && differ) s.best[m] = *best;
  }
  return s;
}

AbSummary summarise_ab(const std::vector<BatchResult>& results) {
  AbSummary summary;
  // Paired by seed: the same scenario and noise for both graphs.
  std::map<std::string, AbRow> rows;
  for (std::size_t s = 0; 2 * s + 1 < results.size(); ++s) {
    const auto& a = results[2 * s];
    const auto& b = results[2 * s + 1];
    summary.meta.add(a.report);
    summary.meta.add(b.report);
    if (a.exit_code != 0 || b.exit_code != 0) {
      ++summary.failed_seeds;
      continue;
    }
    const Metrics ma = report_metrics(a.report), mb = report_metrics(b.report);
    for (const auto& [k, va] : ma)
      if (const auto it = mb.find(k); it != mb.end()) {
        AbRow& row = rows[k];
        row.metric = k;
        if (std::isnan(va) || std::isnan(it->second)) {  // undefined on one side: no pair
          ++row.undefined;
          continue;
        }
        row.seeds.push_back(static_cast<int>(s) + 1);
        row.a.push_back(va);
        row.b.push_back(it->second);
      }
  }
  for (auto& [metric, row] : rows) {
    row.by_magnitude = summary.meta.by_magnitude(metric);
    row.difference =
        row.by_magnitude ? paired_difference(magnitudes(row.a), magnitudes(row.b)) : paired_difference(row.a, row.b);
    row.better = row.seeds.empty() ? "" : verdict(row.difference, summary.meta.direction(metric));
    summary.rows.push_back(row);
  }
  return summary;
}

}  // namespace kestrel::cli
