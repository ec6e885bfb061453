// The parts of `kestrel sweep` and `kestrel ab` on their own: planning the runs, the statistics,
// and what the summaries say about reports whose numbers are known.
#include <gmock/gmock.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "experiment_analysis.hpp"
#include "experiment_output.hpp"
#include "kestrel/error.hpp"
#include "metrics_meta.hpp"
#include "run_plan.hpp"
#include "statistics.hpp"

using namespace kestrel::cli;
namespace fs = std::filesystem;
using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::StartsWith;

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

TEST(MetricsMeta, DescribesMetricsAndTheirParts) {
  MetricsMeta meta;
  meta.add({{"metrics_meta",
             {{"tracking.lag_s", {{"unit", "s"}, {"higher_is_better", false}, {"by_magnitude", true}}},
              {"tracking.mota", {{"unit", ""}, {"higher_is_better", true}}},
              {"detection.rmse_m", {{"unit", "m"}, {"higher_is_better", false}}},
              {"detection.mean_error_m", {{"unit", "m"}}},
              {"broken", "not an object"}}}});
  EXPECT_EQ(meta.direction("tracking.mota"), 1);
  EXPECT_EQ(meta.direction("tracking.lag_s"), -1);
  EXPECT_TRUE(meta.by_magnitude("tracking.lag_s"));
  EXPECT_EQ(meta.direction("detection.rmse_m.x"), -1);  // its parent's entry
  EXPECT_EQ(meta.direction("detection.mean_error_m.x"), 0);
  EXPECT_EQ(meta.direction("tracking.idsw"), 0);  // not described
  EXPECT_EQ(meta.direction("broken"), 0);
  EXPECT_EQ(meta.label("tracking.lag_s"), "tracking.lag_s [s]");
  EXPECT_EQ(meta.label("detection.rmse_m.z"), "detection.rmse_m.z [m]");
  EXPECT_EQ(meta.label("tracking.mota"), "tracking.mota");
  EXPECT_EQ(meta.label("tracking.idsw"), "tracking.idsw");
  EXPECT_EQ(meta.better_text("tracking.lag_s"), "smaller magnitude is better");
  EXPECT_EQ(meta.better_text("tracking.mota"), "higher is better");
  EXPECT_EQ(meta.better_text("tracking.idsw"), "");
  EXPECT_EQ(meta.to_json().at("tracking.lag_s").at("by_magnitude"), true);
  // A second report that agrees changes nothing; one that disagrees takes the direction away.
  meta.add({{"metrics_meta", {{"tracking.mota", {{"unit", ""}, {"higher_is_better", true}}}}}});
  EXPECT_TRUE(meta.conflicts().empty());
  meta.add({{"metrics_meta", {{"tracking.mota", {{"unit", ""}, {"higher_is_better", false}}}}}});
  EXPECT_EQ(meta.direction("tracking.mota"), 0);
  EXPECT_THAT(meta.conflicts(), ElementsAre("tracking.mota"));
  // Reports without metrics_meta add nothing.
  meta.add(nullptr);
  meta.add({{"tracking", {{"mota", 1}}}});
}

namespace {

const nlohmann::json kSweepMeta = {
    {"tracking.score", {{"unit", ""}, {"higher_is_better", true}}},
    {"tracking.error_m", {{"unit", "m"}, {"higher_is_better", false}}},
    {"tracking.lag_s", {{"unit", "s"}, {"higher_is_better", false}, {"by_magnitude", true}}}};

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / (name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  return dir;
}

std::string read(const fs::path& file) {
  std::ifstream in(file);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace

// Three values of a.x, two seeds each, with synthetic reports: score rises with x, error falls,
// lag crosses zero (smallest in magnitude at x = 2), frames never change, spread changes from
// seed to seed only and has no meta.
TEST(SweepOutputs, LabelJudgeAndPlotByMetricsMeta) {
  SweepArgs args;
  args.graph = "g.yaml";
  args.params = {"a.x=1:3:1"};
  args.seeds = 2;
  args.report_dir = fresh_dir("kestrel-sweep-outputs").string();
  const SweepPlan plan = plan_sweep(args);
  std::vector<BatchResult> results;
  for (std::size_t j = 0; j < plan.jobs.size(); ++j) {
    const double x = std::stod(plan.grid[plan.point_of(j)][0]), seed = plan.seed_of(j);
    BatchResult r;
    r.report = {{"tracking",
                 {{"score", x / 10},
                  {"error_m", 1 / x},
                  {"lag_s", 0.2 * (x - 2) + 0.01 * seed},
                  {"frames", 100},
                  {"spread", seed}}},
                {"metrics_meta", kSweepMeta}};
    results.push_back(r);
  }
  const SweepSummary summary = summarise_sweep(plan, results);
  EXPECT_THAT(summary.varying, ElementsAre("tracking.error_m", "tracking.lag_s", "tracking.score"));
  ASSERT_EQ(summary.best.count("tracking.score"), 1u);
  EXPECT_EQ(summary.best.at("tracking.score").point, 2u);
  EXPECT_EQ(summary.best.at("tracking.error_m").point, 2u);
  EXPECT_EQ(summary.best.at("tracking.lag_s").point, 1u);  // mean |lag| 0.015 at x = 2
  EXPECT_NEAR(summary.best.at("tracking.lag_s").value, 0.015, 1e-12);
  EXPECT_EQ(summary.best.count("tracking.spread"), 0u);  // no direction

  const std::string md = write_sweep_outputs(args.report_dir, args.graph, plan, summary);
  EXPECT_THAT(md, HasSubstr("| a.x | tracking.error_m [m] | tracking.lag_s [s] | tracking.score |\n"));
  EXPECT_THAT(md, HasSubstr("| 2 | 0.5 | 0.015 | 0.2 |\n"));
  // Seed to seed only, or not at all: the same mean at every point.
  EXPECT_THAT(md, HasSubstr("The same at every point: tracking.frames = 100, tracking.spread = 1.5."));
  EXPECT_THAT(md, HasSubstr("- tracking.score (higher is better): 0.3 at a.x=3\n"));
  EXPECT_THAT(md, HasSubstr("- tracking.error_m [m] (lower is better): 0.3333 at a.x=3\n"));
  EXPECT_THAT(md, HasSubstr("- tracking.lag_s [s] (smaller magnitude is better): 0.015 at a.x=2\n"));
  EXPECT_THAT(md, Not(HasSubstr("tracking.spread (")));
  const fs::path dir = args.report_dir;
  EXPECT_EQ(read(dir / "sweep.md"), md);
  EXPECT_TRUE(fs::exists(dir / "sweep.png"));
  EXPECT_THAT(read(dir / "sweep.csv"),
              StartsWith("a.x,seed,exit_code,tracking.error_m,tracking.frames,tracking.lag_s,tracking.score,"
                         "tracking.spread\n1,1,0,1,100,"));
  EXPECT_EQ(nlohmann::json::parse(read(dir / "metrics_meta.json")).at("metrics_meta"), kSweepMeta);
}

TEST(AbOutputs, VerdictsUnitsAndMagnitudesInTheFiles) {
  const nlohmann::json meta = kSweepMeta;
  std::vector<BatchResult> results;
  for (int seed = 1; seed <= 3; ++seed)
    for (const double side : {0.0, 1.0}) {
      BatchResult r;
      r.report = {{"tracking",
                   {{"score", 0.5 + 0.1 * side + 0.01 * seed},
                    {"error_m", 0.2 + 0.01 * seed},
                    {"lag_s", side ? 0.01 * seed : -0.3 - 0.01 * seed},
                    {"spread", seed + side}}},
                  {"metrics_meta", meta}};
      results.push_back(r);
    }
  const AbSummary summary = summarise_ab(results);
  AbArgs args;
  args.graph_a = "a.yaml";
  args.graph_b = "b.yaml";
  args.seeds = 3;
  const fs::path dir = fresh_dir("kestrel-ab-outputs");
  const std::string md = write_ab_outputs(dir, args, summary);
  EXPECT_THAT(md, HasSubstr("| tracking.score | 0.52 | 0.62 | +0.1 | [+0.1, +0.1] | B |"));
  EXPECT_THAT(md, HasSubstr("| tracking.error_m [m] | 0.22 | 0.22 | +0 | [+0, +0] | equal |"));
  EXPECT_THAT(md, HasSubstr("| tracking.lag_s [s] (magnitude) | 0.32 | 0.02 | -0.3 |"));
  EXPECT_THAT(md, HasSubstr("| tracking.spread | 2 | 3 | +1 | [+1, +1] | n/a |"));
  EXPECT_THAT(md, HasSubstr("n/a: the reports' metrics_meta does not say which way is better."));
  const auto json = nlohmann::json::parse(read(dir / "ab.json"));
  EXPECT_EQ(json.at("metrics").at("tracking.score").at("better"), "B");
  EXPECT_EQ(json.at("metrics").at("tracking.lag_s").at("better"), "B");
  EXPECT_EQ(json.at("metrics").at("tracking.lag_s").at("by_magnitude"), true);
  EXPECT_TRUE(json.at("metrics").at("tracking.spread").at("better").is_null());
  EXPECT_EQ(json.at("metrics_meta"), meta);
  EXPECT_TRUE(fs::exists(dir / "ab.png"));
}

// A metric a report gives as null (undefined) is left out of the means and counted: per grid
// point in sweep.md, as an empty cell in sweep.csv, per metric in ab.md and ab.json.
TEST(SweepOutputs, UndefinedMetricsAreLeftOutOfMeansAndCounted) {
  SweepArgs args;
  args.graph = "g.yaml";
  args.params = {"a.x=1:2:1"};
  args.seeds = 3;
  args.report_dir = fresh_dir("kestrel-sweep-undefined").string();
  const SweepPlan plan = plan_sweep(args);
  std::vector<BatchResult> results;
  for (std::size_t j = 0; j < plan.jobs.size(); ++j) {
    const double x = std::stod(plan.grid[plan.point_of(j)][0]);
    const int seed = plan.seed_of(j);
    BatchResult r;
    // At x = 1, seed 1 finds nothing: its precision is undefined. At x = 2 no seed defines it.
    const nlohmann::json precision = (x == 1 && seed != 1) ? nlohmann::json(0.5 + 0.1 * seed) : nlohmann::json();
    r.report = {{"detection", {{"precision", precision}, {"frames", 10}}}, {"metrics_meta", kSweepMeta}};
    results.push_back(r);
  }
  const SweepSummary summary = summarise_sweep(plan, results);
  EXPECT_NEAR(summary.means[0].at("detection.precision"), 0.75, 1e-12);  // seeds 2 and 3 only
  EXPECT_EQ(summary.undefined[0].at("detection.precision"), 1u);
  EXPECT_TRUE(std::isnan(summary.means[1].at("detection.precision")));
  EXPECT_EQ(summary.undefined[1].at("detection.precision"), 3u);
  const std::string md = write_sweep_outputs(args.report_dir, args.graph, plan, summary);
  EXPECT_THAT(md, HasSubstr("| 1 | 0.75 (1 of 3 n/a) |\n| 2 | n/a |\n"));
  EXPECT_THAT(md, HasSubstr("n/a: undefined (the report gave null"));
  const std::string csv = read(fs::path(args.report_dir) / "sweep.csv");
  EXPECT_THAT(csv, HasSubstr("\n1,1,0,10,\n1,2,0,10,0.7\n"));  // an empty cell, not "nan"
  EXPECT_THAT(csv, Not(HasSubstr("nan")));
}

TEST(AbOutputs, UndefinedMetricsAreLeftOutOfThePairsAndCounted) {
  std::vector<BatchResult> results;
  for (int seed = 1; seed <= 4; ++seed)
    for (const int side : {0, 1}) {
      BatchResult r;
      // B has no lag on seed 2 (too few samples); nobody has a precision.
      const nlohmann::json lag = side == 1 && seed == 2 ? nlohmann::json() : nlohmann::json(0.1 * seed + 0.05 * side);
      r.report = {{"tracking", {{"lag_s", lag}, {"precision", nullptr}}}, {"metrics_meta", kSweepMeta}};
      results.push_back(r);
    }
  const AbSummary summary = summarise_ab(results);
  ASSERT_EQ(summary.rows.size(), 2u);
  const AbRow& lag = summary.rows[0];
  EXPECT_EQ(lag.metric, "tracking.lag_s");
  EXPECT_THAT(lag.seeds, ElementsAre(1, 3, 4));
  EXPECT_EQ(lag.undefined, 1u);
  EXPECT_NEAR(lag.difference.mean_difference, 0.05, 1e-12);
  EXPECT_EQ(summary.rows[1].undefined, 4u);
  EXPECT_TRUE(summary.rows[1].seeds.empty());
  AbArgs args;
  args.graph_a = "a.yaml";
  args.graph_b = "b.yaml";
  args.seeds = 4;
  const fs::path dir = fresh_dir("kestrel-ab-undefined");
  const std::string md = write_ab_outputs(dir, args, summary);
  EXPECT_THAT(md, HasSubstr("| tracking.lag_s [s] (magnitude) (1 of 4 seeds n/a) | 0.2667 | 0.3167 | +0.05 |"));
  EXPECT_THAT(md, HasSubstr("| tracking.precision (4 of 4 seeds n/a) | n/a | n/a | n/a | n/a | n/a |"));
  const auto json = nlohmann::json::parse(read(dir / "ab.json"));
  EXPECT_EQ(json.at("metrics").at("tracking.lag_s").at("undefined_seeds"), 1);
  EXPECT_EQ(json.at("metrics").at("tracking.lag_s").at("seeds"), 3);
  EXPECT_EQ(json.at("metrics").at("tracking.precision").at("undefined_seeds"), 4);
  EXPECT_TRUE(json.at("metrics").at("tracking.precision").at("mean_a").is_null());
}
