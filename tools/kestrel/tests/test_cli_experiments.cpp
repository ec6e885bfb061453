// The parts of `kestrel sweep` and `kestrel ab` on their own: planning the runs, the statistics,
// and what the summaries say about reports whose numbers are known.
#include <gmock/gmock.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "command_errors.hpp"
#include "csv_format.hpp"
#include "experiment_analysis.hpp"
#include "experiment_output.hpp"
#include "kestrel/error.hpp"
#include "kestrel/testing/read_file.hpp"
#include "kestrel/testing/scratch_path.hpp"
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

using kestrel::testing::read_file;

namespace {

const nlohmann::json kSweepMeta = {
    {"tracking.score", {{"unit", ""}, {"higher_is_better", true}}},
    {"tracking.error_m", {{"unit", "m"}, {"higher_is_better", false}}},
    {"tracking.lag_s", {{"unit", "s"}, {"higher_is_better", false}, {"by_magnitude", true}}}};

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = kestrel::testing::scratch_path(name);
  fs::remove_all(dir);
  return dir;
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
  EXPECT_EQ(read_file(dir / "sweep.md"), md);
  EXPECT_TRUE(fs::exists(dir / "sweep.png"));
  EXPECT_THAT(read_file(dir / "sweep.csv"),
              StartsWith("a.x,seed,exit_code,tracking.error_m,tracking.frames,tracking.lag_s,tracking.score,"
                         "tracking.spread\n1,1,0,1,100,"));
  EXPECT_EQ(nlohmann::json::parse(read_file(dir / "metrics_meta.json")).at("metrics_meta"), kSweepMeta);
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
  const auto json = nlohmann::json::parse(read_file(dir / "ab.json"));
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
  const std::string csv = read_file(fs::path(args.report_dir) / "sweep.csv");
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
  const auto json = nlohmann::json::parse(read_file(dir / "ab.json"));
  EXPECT_EQ(json.at("metrics").at("tracking.lag_s").at("undefined_seeds"), 1);
  EXPECT_EQ(json.at("metrics").at("tracking.lag_s").at("seeds"), 3);
  EXPECT_EQ(json.at("metrics").at("tracking.precision").at("undefined_seeds"), 4);
  EXPECT_TRUE(json.at("metrics").at("tracking.precision").at("mean_a").is_null());
}

namespace {

// A cases file in a fresh folder; the plan's report folder is "out".
SweepArgs cases_args(const std::string& name, const std::string& text) {
  const fs::path dir = fresh_dir(name);
  fs::create_directories(dir);
  std::ofstream(dir / "cases.csv") << text;
  SweepArgs args;
  args.graph = "g.yaml";
  args.cases = (dir / "cases.csv").string();
  args.report_dir = "out";
  return args;
}

// The message of the kestrel::Error that planning throws, or "" if it throws none.
std::string plan_error(const SweepArgs& args) {
  try {
    plan_sweep(args);
  } catch (const kestrel::Error& e) {
    return e.what();
  }
  return "";
}

// The exit code of the CommandError that planning throws, or -1.
int plan_exit_code(const SweepArgs& args) {
  try {
    plan_sweep(args);
  } catch (const CommandError& e) {
    return e.code();
  }
  return -1;
}

}  // namespace

TEST(RunPlan, CasesWithASeedColumnRunOnceEachWithTheirSeed) {
  SweepArgs args = cases_args("kestrel-cases-seeded",
                              "# drawn by a script\n"
                              "tracker.filter.r,seed,intruder.shape\n"
                              "0.5,7,line\n"
                              "\n"
                              "2.0,3,figure8\n"
                              "1.25,7,circle\n");
  args.overrides = {"c.z=3"};
  args.duration = 2;
  const SweepPlan plan = plan_sweep(args);
  EXPECT_TRUE(plan.from_cases());
  EXPECT_TRUE(plan.case_seeds);
  ASSERT_EQ(plan.params.size(), 2u);
  EXPECT_EQ(plan.params[0].key, "tracker.filter.r");
  EXPECT_EQ(plan.params[1].key, "intruder.shape");
  ASSERT_EQ(plan.grid.size(), 3u);
  EXPECT_THAT(plan.grid[1], ElementsAre("2.0", "figure8"));
  EXPECT_THAT(plan.case_lines, ElementsAre(3, 5, 6));  // lines in the file: comments and blanks count
  ASSERT_EQ(plan.jobs.size(), 3u);
  EXPECT_THAT(plan.job_seeds, ElementsAre(7, 3, 7));
  EXPECT_EQ(plan.point_of(2), 2u);
  EXPECT_EQ(plan.seed_of(1), 3);
  EXPECT_EQ(plan.jobs[1].report_dir, fs::path("out/runs/001_seed3"));
  EXPECT_THAT(plan.jobs[1].args, ElementsAre("run", "g.yaml", "--seed", "3", "--report", "out/runs/001_seed3",
                                             "--no-progress", "--set", "c.z=3", "--set", "tracker.filter.r=2.0",
                                             "--set", "intruder.shape=figure8", "--duration", "2"));
  // Two cases may share a seed: their folders differ by the case's number.
  EXPECT_EQ(plan.jobs[2].report_dir, fs::path("out/runs/002_seed7"));
}

TEST(RunPlan, CasesWithoutASeedColumnRunSeedsOneToN) {
  SweepArgs args = cases_args("kestrel-cases-unseeded", "a.x,b.y\r\n1,2\r\n3,4\r\n");  // as Python's csv writes
  const SweepPlan one = plan_sweep(args);
  EXPECT_FALSE(one.case_seeds);
  ASSERT_EQ(one.jobs.size(), 2u);  // one seed without --seeds
  EXPECT_THAT(one.job_seeds, ElementsAre(1, 1));
  EXPECT_THAT(one.grid[1], ElementsAre("3", "4"));  // no \r left in the last cell
  args.seeds = 3;
  const SweepPlan plan = plan_sweep(args);
  ASSERT_EQ(plan.jobs.size(), 6u);
  EXPECT_THAT(plan.job_points, ElementsAre(0, 0, 0, 1, 1, 1));
  EXPECT_THAT(plan.job_seeds, ElementsAre(1, 2, 3, 1, 2, 3));
  EXPECT_EQ(plan.point_of(4), 1u);
  EXPECT_EQ(plan.seed_of(4), 2);
  EXPECT_EQ(plan.jobs[4].report_dir, fs::path("out/runs/001_seed2"));
  EXPECT_THAT(plan.sets_for(1), ElementsAre("a.x=3", "b.y=4"));
}

TEST(RunPlan, CaseCellsMayBeQuotedToHoldCommasAndQuotes) {
  const SweepPlan plan = plan_sweep(cases_args("kestrel-cases-quoted",
                                               "intruder.waypoints,n.label,tracker.filter.r\n"
                                               "\"[1.0, 2.0, 3.0]\",\"say \"\"hi\"\"\",1\n"
                                               "\"[4, 5]\",\"\",2\n"));
  ASSERT_EQ(plan.grid.size(), 2u);
  EXPECT_THAT(plan.grid[0], ElementsAre("[1.0, 2.0, 3.0]", "say \"hi\"", "1"));
  EXPECT_THAT(plan.sets_for(0),
              ElementsAre("intruder.waypoints=[1.0, 2.0, 3.0]", "n.label=say \"hi\"", "tracker.filter.r=1"));
  // A quoted empty cell is empty too: not set.
  EXPECT_THAT(plan.sets_for(1), ElementsAre("intruder.waypoints=[4, 5]", "tracker.filter.r=2"));
}

TEST(RunPlan, AnEmptyCaseCellLeavesTheParameterUnset) {
  SweepArgs args = cases_args("kestrel-cases-empty", "a.x,b.y,seed\n1,,4\n,2,5\n");
  args.overrides = {"c.z=3"};
  const SweepPlan plan = plan_sweep(args);
  EXPECT_THAT(plan.sets_for(0), ElementsAre("c.z=3", "a.x=1"));
  EXPECT_THAT(plan.sets_for(1), ElementsAre("c.z=3", "b.y=2"));
  EXPECT_THAT(plan.jobs[0].args, Not(::testing::Contains(StartsWith("b.y"))));
  EXPECT_THAT(plan.jobs[1].args, Not(::testing::Contains(StartsWith("a.x"))));
  EXPECT_THAT(plan.grid[1], ElementsAre("", "2"));  // sweep.csv keeps the cell empty
}

// Each malformed file is refused with the file and the line (and column for a quote), exit 2.
TEST(RunPlan, MalformedCaseFilesAreRefusedAtTheirLine) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"a.x,b.y\n1,2\n3\n", ":3: 1 cell(s), but the header has 2 column(s)"},
      {"a.x,b.y\n1,2,3\n", ":2: 3 cell(s), but the header has 2 column(s)"},
      {"a.x\n\"[1, 2\n", ":2:1: unterminated quote"},
      {"a.x,b.y\n\"1\"x,2\n", ":2:4: a comma or the end of the line must follow a closing quote"},
      {"# comment\na.x,,b.y\n1,2,3\n", ":2: column 2 has no name"},
      {"a.x,speed\n1,2\n", ":1: a column is a node.param (as --set takes it) or seed, not 'speed'"},
      {"a.x,.y\n1,2\n", ":1: a column is a node.param (as --set takes it) or seed, not '.y'"},
      {"a.x,seed\n1,0\n", ":2: the seed must be a whole number >= 1, not '0'"},
      {"a.x,seed\n1,1\n2,-3\n", ":3: the seed must be a whole number >= 1, not '-3'"},
      {"a.x,seed\n1,1.5\n", ":2: the seed must be a whole number >= 1, not '1.5'"},
      {"a.x,seed\n1,x\n", ":2: the seed must be a whole number >= 1, not 'x'"},
      {"a.x,seed\n1,\n", ":2: the seed must be a whole number >= 1, not ''"},
      {"a.x,seed\n1,99999999999\n", ":2: the seed must be a whole number >= 1, not '99999999999'"},
      {"a.x,b.y,a.x\n1,2,3\n", ":1: column 'a.x' appears twice"},
      {"a.x,seed,seed\n1,2,3\n", ":1: column 'seed' appears twice"},
      {"a.x,b.y\n\n# nothing drawn\n", ":1: no cases: the header is the last row"},
      {"", ": no header row"},
  };
  for (const auto& [text, message] : cases) {
    const SweepArgs args = cases_args("kestrel-cases-bad", text);
    EXPECT_THAT(plan_error(args), HasSubstr(args.cases + message)) << text;
    EXPECT_EQ(run_command_body("sweep", [&] { return static_cast<int>(plan_sweep(args).jobs.size()); }), kUsage)
        << text;
  }
  SweepArgs missing;
  missing.cases = (fresh_dir("kestrel-cases-missing") / "none.csv").string();
  EXPECT_EQ(plan_error(missing), "cannot open the cases file " + missing.cases);
}

TEST(RunPlan, SeedsAreRefusedWithASeedColumn) {
  SweepArgs args = cases_args("kestrel-cases-seeds", "a.x,seed\n1,4\n");
  args.seeds = 2;
  EXPECT_EQ(plan_exit_code(args), kUsage);
  EXPECT_THAT(plan_error(args), HasSubstr("--seeds cannot be given with " + args.cases));
  args.seeds = std::nullopt;
  EXPECT_EQ(plan_sweep(args).jobs.size(), 1u);
}

TEST(RunPlan, ExactlyOneOfParamAndCases) {
  SweepArgs both = cases_args("kestrel-cases-both", "a.x\n1\n");
  both.params = {"a.x=1:2:1"};
  EXPECT_EQ(plan_exit_code(both), kUsage);
  EXPECT_THAT(plan_error(both), HasSubstr("either --param (a grid) or --cases (a table of cases), not both"));
  SweepArgs neither;
  neither.graph = "g.yaml";
  neither.report_dir = "out";
  EXPECT_EQ(plan_exit_code(neither), kUsage);
  EXPECT_THAT(plan_error(neither), HasSubstr("--param node.param=start:stop:step"));
  EXPECT_THAT(plan_error(neither), HasSubstr("--cases FILE.csv"));
}

// sweep.csv quotes a value with commas as a CSV reader expects; sweep.md numbers the cases and
// says where they come from; sweep.png plots per case, whatever the values are.
TEST(SweepOutputs, CasesAreNumberedQuotedAndPlottedPerCase) {
  SweepArgs args = cases_args("kestrel-cases-outputs",
                              "intruder.shape,intruder.waypoints,seed\n"
                              "line,\"[1, 2]\",4\n"
                              "circle,,9\n"
                              "line,\"[3, 4]\",2\n");
  args.report_dir = fresh_dir("kestrel-cases-outputs-report").string();
  const SweepPlan plan = plan_sweep(args);
  std::vector<BatchResult> results;
  for (std::size_t j = 0; j < plan.jobs.size(); ++j) {
    BatchResult r;
    r.report = {{"tracking", {{"score", 0.1 * static_cast<double>(j)}}}, {"metrics_meta", kSweepMeta}};
    results.push_back(r);
  }
  const SweepSummary summary = summarise_sweep(plan, results);
  const std::string md = write_sweep_outputs(args.report_dir, args.graph, plan, summary);
  EXPECT_THAT(md, HasSubstr("3 runs (3 cases from " + args.cases + ", each with its own seed).\n"));
  EXPECT_THAT(md, HasSubstr("| case | seed | intruder.shape | intruder.waypoints | tracking.score |\n"));
  EXPECT_THAT(md, HasSubstr("| 1 | 9 | circle | not set | 0.1 |\n"));
  EXPECT_THAT(md, HasSubstr("- tracking.score (higher is better): 0.2 at case 2 (intruder.shape=line, "
                            "intruder.waypoints=[3, 4])\n"));
  EXPECT_THAT(md, HasSubstr("![metrics per case](sweep.png)"));
  EXPECT_TRUE(fs::exists(fs::path(args.report_dir) / "sweep.png"));
  EXPECT_EQ(read_file(fs::path(args.report_dir) / "sweep.csv"),
            "intruder.shape,intruder.waypoints,seed,exit_code,tracking.score\n"
            "line,\"[1, 2]\",4,0,0\n"
            "circle,,9,0,0.1\n"
            "line,\"[3, 4]\",2,0,0.2\n");

  args.cases = cases_args("kestrel-cases-outputs-unseeded", "a.x\n1\n2\n").cases;
  args.seeds = 2;
  const SweepPlan unseeded = plan_sweep(args);
  std::vector<BatchResult> runs(unseeded.jobs.size());
  for (std::size_t j = 0; j < runs.size(); ++j) runs[j].report = {{"tracking", {{"score", 1.0 * j}}}};
  EXPECT_THAT(write_sweep_outputs(args.report_dir, args.graph, unseeded, summarise_sweep(unseeded, runs)),
              HasSubstr("4 runs (2 cases from " + args.cases + " x 2 seeds); mean over seeds.\n"));
}

// A grid whose first parameter is not a number is plotted per point instead of failing.
TEST(SweepOutputs, AGridOfWordsIsPlottedPerPoint) {
  SweepPlan plan;
  plan.params = {{"intruder.shape", {"line", "circle"}}};
  plan.grid = {{"line"}, {"circle"}};
  plan.job_points = {0, 1};
  plan.job_seeds = {1, 1};
  plan.jobs.resize(2);
  std::vector<BatchResult> results(2);
  results[0].report = {{"tracking", {{"score", 0.5}}}};
  results[1].report = {{"tracking", {{"score", 0.7}}}};
  const fs::path dir = fresh_dir("kestrel-sweep-words");
  std::string md;
  ASSERT_NO_THROW(md = write_sweep_outputs(dir, "g.yaml", plan, summarise_sweep(plan, results)));
  EXPECT_THAT(md, HasSubstr("| line | 0.5 |\n| circle | 0.7 |\n"));
  EXPECT_THAT(md, HasSubstr("![metrics per point](sweep.png)"));
  EXPECT_TRUE(fs::exists(dir / "sweep.png"));
}

TEST(CsvFormat, QuotesWhatARecordWouldSplitAndReadsItBack) {
  EXPECT_EQ(csv_cell("1.5"), "1.5");
  EXPECT_EQ(csv_cell("[1, 2]"), "\"[1, 2]\"");
  EXPECT_EQ(csv_cell("say \"hi\""), "\"say \"\"hi\"\"\"");
  std::istringstream in(csv_cell("[1, 2]") + "," + csv_cell("say \"hi\"") + ",,x\n");
  const auto records = read_csv(in, "t.csv");
  ASSERT_EQ(records.size(), 1u);
  EXPECT_THAT(records[0].cells, ElementsAre("[1, 2]", "say \"hi\"", "", "x"));
}
