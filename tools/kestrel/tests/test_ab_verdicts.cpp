// What `kestrel ab` says about A and B, on data whose answer is known: which side is better
// follows each metric's metrics_meta (higher or lower is better, or by magnitude), and a metric
// without a direction gets no verdict.
#include <gmock/gmock.h>

#include <nlohmann/json.hpp>
#include <stdexcept>

#include "experiment_analysis.hpp"

using namespace kestrel::cli;

namespace {

const nlohmann::json kMeta = {
    {"tracking.score", {{"unit", ""}, {"higher_is_better", true}}},
    {"tracking.error_m", {{"unit", "m"}, {"higher_is_better", false}}},
    {"tracking.lag_s", {{"unit", "s"}, {"higher_is_better", false}, {"by_magnitude", true}}},
    {"tracking.bias_m", {{"unit", "m"}}},
    {"detection.rmse_m", {{"unit", "m"}, {"higher_is_better", false}}},
};

// Five seeds of a metric; B is higher than A by about 0.1 on every seed, or by noise only.
const std::vector<double> kA = {0.60, 0.62, 0.58, 0.61, 0.59};
const std::vector<double> kHigher = {0.70, 0.74, 0.67, 0.72, 0.69};  // + 0.10, 0.12, 0.09, 0.11, 0.10
const std::vector<double> kNoise = {0.62, 0.60, 0.59, 0.60, 0.59};   // + 0.02, -0.02, 0.01, -0.01, 0

// A run whose report holds one metric (a dotted path) and the given metrics_meta.
BatchResult run_with(const std::string& metric, double value, const nlohmann::json& meta) {
  BatchResult r;
  r.report = {{"outcome", "completed"}};
  std::string pointer = "/" + metric;
  std::replace(pointer.begin(), pointer.end(), '.', '/');
  r.report[nlohmann::json::json_pointer(pointer)] = value;
  if (!meta.is_null()) r.report["metrics_meta"] = meta;
  return r;
}

// The runs of an A/B comparison of one metric: A and B alternating, seed by seed.
std::vector<BatchResult> ab_runs(const std::string& metric, const std::vector<double>& a, const std::vector<double>& b,
                                 const nlohmann::json& meta_a = kMeta, const nlohmann::json& meta_b = kMeta) {
  std::vector<BatchResult> results;
  for (std::size_t i = 0; i < a.size(); ++i) {
    results.push_back(run_with(metric, a[i], meta_a));
    results.push_back(run_with(metric, b[i], meta_b));
  }
  return results;
}

AbRow compare(const std::string& metric, const std::vector<double>& a, const std::vector<double>& b,
              const nlohmann::json& meta_a = kMeta, const nlohmann::json& meta_b = kMeta) {
  for (const auto& row : summarise_ab(ab_runs(metric, a, b, meta_a, meta_b)).rows)
    if (row.metric == metric) return row;
  throw std::runtime_error("no row for " + metric);
}

}  // namespace

TEST(AbVerdict, HigherIsBetter) {
  const AbRow row = compare("tracking.score", kA, kHigher);
  EXPECT_EQ(row.better, "B");
  // d = 0.10, 0.12, 0.09, 0.11, 0.10: mean 0.104, sd 0.0114018, t(0.975, 4) = 2.776445.
  EXPECT_NEAR(row.difference.mean_difference, 0.104, 1e-12);
  EXPECT_NEAR(row.difference.ci95.low, 0.0898428, 1e-6);
  EXPECT_NEAR(row.difference.ci95.high, 0.1181572, 1e-6);
  EXPECT_EQ(compare("tracking.score", kHigher, kA).better, "A");
}

TEST(AbVerdict, LowerIsBetter) {
  EXPECT_EQ(compare("tracking.error_m", kA, kHigher).better, "A");
  EXPECT_EQ(compare("tracking.error_m", kHigher, kA).better, "B");
  // Described by its parent: "detection.rmse_m" covers its axes.
  EXPECT_EQ(compare("detection.rmse_m.x", kA, kHigher).better, "A");
}

TEST(AbVerdict, NoSignificantDifference) {
  EXPECT_EQ(compare("tracking.score", kA, kNoise).better, "no significant difference");
  EXPECT_EQ(compare("tracking.error_m", kA, kNoise).better, "no significant difference");
  EXPECT_EQ(compare("tracking.score", kA, kA).better, "equal");
}

// A lag is as bad early as late: B, closer to zero on every seed, is better, though its signed
// lag is larger.
TEST(AbVerdict, LagIsComparedByMagnitude) {
  const std::vector<double> late = {-0.30, -0.25, -0.35, -0.28}, close = {0.05, -0.02, 0.04, 0.01};
  const AbRow row = compare("tracking.lag_s", late, close);
  EXPECT_EQ(row.better, "B");
  EXPECT_TRUE(row.by_magnitude);
  EXPECT_NEAR(row.difference.mean_a, 0.295, 1e-12);  // mean magnitudes
  EXPECT_NEAR(row.difference.mean_b, 0.03, 1e-12);
  EXPECT_EQ(row.a, late);  // the values as reported, for the plot
  EXPECT_EQ(compare("tracking.lag_s", close, late).better, "A");
  EXPECT_EQ(compare("tracking.lag_s", late, {0.30, 0.25, 0.35, 0.28}).better, "equal");  // mirror images
}

// No key lists: a metric that metrics_meta does not judge gets no verdict, whatever its name.
TEST(AbVerdict, NoVerdictWithoutADirection) {
  EXPECT_EQ(compare("tracking.bias_m", kA, kHigher).better, "");                  // a unit, no direction
  EXPECT_EQ(compare("tracking.rmse_m", kA, kHigher).better, "");                  // not described at all
  EXPECT_EQ(compare("tracking.mota", kA, kHigher, nullptr, nullptr).better, "");  // reports without meta
  EXPECT_EQ(compare("tracking.mota", kA, kA, nullptr, nullptr).better, "equal");
  // A and B disagree on the direction: no verdict rather than a guess.
  nlohmann::json flipped = kMeta;
  flipped["tracking.score"]["higher_is_better"] = false;
  EXPECT_EQ(compare("tracking.score", kA, kHigher, kMeta, flipped).better, "");
}
