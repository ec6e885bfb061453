#pragma once
// What the runs of a sweep or an A/B comparison say: metrics per run, means over seeds, and for
// A/B the paired difference of each metric with a verdict on which side is better. Which way is
// better, and whether by magnitude, comes from the reports' metrics_meta; a metric they do not
// describe is summarised all the same, without a verdict.
#include <map>
#include <set>
#include <string>
#include <vector>

#include "batch_runs.hpp"
#include "metrics_meta.hpp"
#include "report_metrics.hpp"
#include "run_plan.hpp"
#include "statistics.hpp"

namespace kestrel::cli {

struct SweepSummary {
  std::vector<Metrics> runs;           ///< per job, as planned
  std::vector<int> exit_codes;         ///< per job
  std::set<std::string> metric_names;  ///< every metric of any run
  std::set<std::string> varying;       ///< metrics whose mean differs between grid points
  std::vector<Metrics> means;          ///< per grid point: mean over the seeds where it is defined
  /// Per grid point: how many of its runs reported the metric as undefined (null).
  std::vector<std::map<std::string, std::size_t>> undefined;
  std::vector<std::size_t> runs_per_point;  ///< per grid point
  std::size_t failed = 0;                   ///< runs that exited non-zero
  MetricsMeta meta;

  /// The best grid point of a metric with a direction whose means differ between points.
  struct Best {
    std::size_t point = 0;
    double value = 0.0;    ///< its mean over seeds (of magnitudes, for a by-magnitude metric)
    std::size_t ties = 0;  ///< other points with the same mean
  };
  std::map<std::string, Best> best;
};

SweepSummary summarise_sweep(const SweepPlan& plan, const std::vector<BatchResult>& results);

/// One metric compared between A and B over the seeds where both runs succeeded and both
/// defined it.
struct AbRow {
  std::string metric;
  std::vector<int> seeds;     ///< where both runs defined the metric
  std::size_t undefined = 0;  ///< seeds left out: the metric was null in A, in B or in both
  std::vector<double> a, b;   ///< per seed, as reported
  bool by_magnitude = false;  ///< the difference is of |a| and |b|
  PairedDifference difference;
  /// "A" or "B" (better with 95% confidence), "no significant difference", "equal" (every pair
  /// equal), or "" when metrics_meta does not say which way is better.
  std::string better;
};

struct AbSummary {
  std::vector<AbRow> rows;  ///< by metric name
  std::size_t failed_seeds = 0;
  MetricsMeta meta;
};

/// results[2(s-1)] is A with seed s, results[2(s-1)+1] is B with seed s (as plan_ab makes them).
AbSummary summarise_ab(const std::vector<BatchResult>& results);

}  // namespace kestrel::cli
