// The parts of `kestrel sweep` and `kestrel ab` on their own: planning the runs, the statistics,
// and what the summaries say about reports whose numbers are known.
#include <gmock/gmock.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "experiment_analysis.hpp"
#include "kestrel/error.hpp"
#include "run_plan.hpp"
#include "statistics.hpp"

using namespace kestrel::cli;
using ::testing::ElementsAre;

TEST(RunPlan, ParsesRangesWithTheStopIncluded) {
  EXPECT_THAT(parse_range("tracker.r=0.5:2:0.5").values, ElementsAre("0.5", "1", "1.5", "2"));
  EXPECT_THAT(parse_range("a.b=0.1:0.3:0.1").values, ElementsAre("0.1", "0.2", "0.3"));
  EXPECT_EQ(parse_range("a.b=1:1:1").key, "a.b");
  EXPECT_THROW(parse_range("a.b"), kestrel::Error);
  EXPECT_THROW(parse_range("a.b=2:1:1"), kestrel::Error);
  EXPECT_THROW(parse_range("a.b=1:2:0"), kestrel::Error);
}

TEST(RunPlan, SweepRunsEveryGridPointWithEverySeed) {
  SweepArgs args;
  args.graph = "g.yaml";
  args.params = {"a.x=1:2:1", "b.y=0:10:5"};
  args.overrides = {"c.z=3"};
  args.seeds = 2;
  args.duration = 1.5;
  args.report_dir = "out";
  const SweepPlan plan = plan_sweep(args);
  ASSERT_EQ(plan.grid.size(), 6u);
  EXPECT_THAT(plan.grid[4], ElementsAre("2", "5"));
  ASSERT_EQ(plan.jobs.size(), 12u);
  EXPECT_EQ(plan.point_of(9), 4u);
  EXPECT_EQ(plan.seed_of(9), 2);
  EXPECT_EQ(plan.jobs[9].report_dir, std::filesystem::path("out/runs/004_seed2"));
  EXPECT_THAT(plan.jobs[9].args,
              ElementsAre("run", "g.yaml", "--seed", "2", "--report", "out/runs/004_seed2", "--no-progress", "--set",
                          "c.z=3", "--set", "a.x=2", "--set", "b.y=5", "--duration", "1.5"));
}

TEST(RunPlan, AbAlternatesTheSidesSeedBySeed) {
  AbArgs args;
  args.graph_a = args.graph_b = "g.yaml";
  args.overrides = {"n.p=1"};
  args.overrides_b = {"n.q=2"};
  args.seeds = 3;
  args.report_dir = "out";
  const AbPlan plan = plan_ab(args);
  ASSERT_EQ(plan.jobs.size(), 6u);
  EXPECT_EQ(plan.jobs[3].report_dir, std::filesystem::path("out/runs/B_seed2"));
  EXPECT_THAT(plan.sets_a, ElementsAre("n.p=1"));
  EXPECT_THAT(plan.sets_b, ElementsAre("n.p=1", "n.q=2"));
  args.seeds = 1;
  EXPECT_THROW(plan_ab(args), kestrel::Error);
}

TEST(Statistics, MeanAndSampleStandardDeviation) {
  EXPECT_DOUBLE_EQ(mean({1, 2, 3, 4}), 2.5);
  EXPECT_TRUE(std::isnan(mean({})));
  EXPECT_NEAR(sample_sd({2, 4, 4, 4, 5, 5, 7, 9}), std::sqrt(32.0 / 7.0), 1e-12);
  EXPECT_EQ(sample_sd({3}), 0.0);
}

// Reference values: Student's t quantiles as printed in statistical tables (and by R's qt).
TEST(Statistics, StudentsTQuantiles) {
  EXPECT_NEAR(t_quantile(0.975, 9), 2.262157, 1e-6);
  EXPECT_NEAR(t_quantile(0.975, 1), 12.706205, 1e-6);
  EXPECT_NEAR(t_quantile(0.975, 40), 2.021075, 1e-6);
  EXPECT_NEAR(t_quantile(0.975, 1000), 1.962339, 1e-6);
  EXPECT_NEAR(t_quantile(0.995, 5), 4.032143, 1e-6);
  EXPECT_NEAR(t_quantile(0.5, 7), 0.0, 1e-12);
  EXPECT_TRUE(std::isnan(t_quantile(0.975, 0)));
}

// Student's sleep data (Biometrika, 1908), paired: R's t.test(extra ~ group, data = sleep,
// paired = TRUE) gives a mean difference of 1.58 with 95% interval [0.7001142, 2.4598858].
TEST(Statistics, PairedDifferenceOfStudentsSleepData) {
  const std::vector<double> a = {0.7, -1.6, -0.2, -1.2, -0.1, 3.4, 3.7, 0.8, 0.0, 2.0};
  const std::vector<double> b = {1.9, 0.8, 1.1, 0.1, -0.1, 4.4, 5.5, 1.6, 4.6, 3.4};
  const PairedDifference d = paired_difference(a, b);
  EXPECT_EQ(d.n, 10u);
  EXPECT_NEAR(d.mean_a, 0.75, 1e-12);
  EXPECT_NEAR(d.mean_b, 2.33, 1e-12);
  EXPECT_NEAR(d.mean_difference, 1.58, 1e-12);
  EXPECT_NEAR(d.sd_difference, 1.2299955, 1e-7);
  EXPECT_NEAR(d.ci95.low, 0.7001142, 1e-7);
  EXPECT_NEAR(d.ci95.high, 2.4598858, 1e-7);
  // One pair has no spread to estimate: no interval.
  EXPECT_TRUE(std::isnan(paired_difference({1}, {2}).ci95.low));
  EXPECT_THROW(paired_difference({1, 2}, {1}), kestrel::Error);
}

namespace {

// A run's result whose report holds the given "tracking" metrics.
BatchResult run_with(const nlohmann::json& tracking, const nlohmann::json& meta = nullptr) {
  BatchResult r;
  r.report = {{"outcome", "completed"}, {"tracking", tracking}};
  if (!meta.is_null()) r.report["metrics_meta"] = meta;
  return r;
}

// The results of an A/B run (A and B alternating, seed by seed) of one metric.
std::vector<BatchResult> ab_results(const std::string& key, const std::vector<double>& a, const std::vector<double>& b,
                                    const nlohmann::json& meta = nullptr) {
  std::vector<BatchResult> results;
  for (std::size_t i = 0; i < a.size(); ++i) {
    results.push_back(run_with({{key, a[i]}}, meta));
    results.push_back(run_with({{key, b[i]}}, meta));
  }
  return results;
}

const AbRow& row_of(const AbSummary& summary, const std::string& metric) {
  for (const auto& row : summary.rows)
    if (row.metric == metric) return row;
  throw std::runtime_error("no row " + metric);
}

}  // namespace

// A lag is as bad early as late: B, closer to zero on every seed, is better, though its signed
// lag is larger.
TEST(AbVerdict, LagIsComparedByMagnitude) {
  const auto summary = summarise_ab(ab_results("lag_s", {-0.30, -0.25, -0.35, -0.28}, {0.05, -0.02, 0.04, 0.01}));
  const AbRow& row = row_of(summary, "tracking.lag_s");
  EXPECT_EQ(row.better, "B");
  EXPECT_NEAR(row.difference.mean_a, 0.295, 1e-12);  // the mean magnitude
  EXPECT_NEAR(row.difference.mean_b, 0.03, 1e-12);
  EXPECT_LT(row.difference.ci95.high, 0);
  // And the other way round.
  EXPECT_EQ(row_of(summarise_ab(ab_results("lag_s", {0.05, -0.02, 0.04, 0.01}, {-0.30, -0.25, -0.35, -0.28})),
                   "tracking.lag_s")
                .better,
            "A");
}
