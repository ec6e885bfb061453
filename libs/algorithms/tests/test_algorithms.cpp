// The shared assignment solver against brute force, and the lag estimator on known shifts.
#include <gmock/gmock.h>

#include <algorithm>
#include <functional>
#include <numeric>
#include <random>

#include "kestrel/algorithms/assignment.hpp"
#include "kestrel/algorithms/clear_mot.hpp"
#include "kestrel/algorithms/lag.hpp"
#include "kestrel/algorithms/mot_metrics.hpp"

using namespace kestrel::algorithms;

namespace {

// Enumerates every partial matching; best = most allowed pairs, then least cost.
std::pair<int, double> brute_force(const Eigen::MatrixXd& cost, double gate) {
  const int rows = static_cast<int>(cost.rows()), cols = static_cast<int>(cost.cols());
  std::pair<int, double> best{0, 0.0};
  std::vector<int> used(static_cast<std::size_t>(cols), 0);
  std::function<void(int, int, double)> visit = [&](int r, int pairs, double total) {
    if (r == rows) {
      if (pairs > best.first || (pairs == best.first && total < best.second - 1e-12)) best = {pairs, total};
      return;
    }
    visit(r + 1, pairs, total);  // leave row r unassigned
    for (int c = 0; c < cols; ++c) {
      if (used[static_cast<std::size_t>(c)] || !std::isfinite(cost(r, c)) || cost(r, c) > gate) continue;
      used[static_cast<std::size_t>(c)] = 1;
      visit(r + 1, pairs + 1, total + cost(r, c));
      used[static_cast<std::size_t>(c)] = 0;
    }
  };
  visit(0, 0, 0.0);
  return best;
}

void expect_consistent(const Assignment& a, const Eigen::MatrixXd& cost, double gate) {
  int pairs = 0;
  double total = 0;
  for (int r = 0; r < cost.rows(); ++r) {
    const int c = a.row_to_col[static_cast<std::size_t>(r)];
    if (c < 0) continue;
    ++pairs;
    total += cost(r, c);
    EXPECT_EQ(a.col_to_row[static_cast<std::size_t>(c)], r);
    EXPECT_TRUE(std::isfinite(cost(r, c)) && cost(r, c) <= gate) << "a forbidden pair was assigned";
  }
  EXPECT_EQ(pairs, a.pairs);
  EXPECT_NEAR(total, a.total_cost, 1e-9);
}

}  // namespace

TEST(Assignment, MatchesBruteForceOnRandomRectangularMatrices) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> size(1, 6);
  std::uniform_real_distribution<double> value(0.0, 3.0);
  std::bernoulli_distribution forbid(0.2);
  for (int trial = 0; trial < 500; ++trial) {
    const int cols = size(rng), rows = size(rng);  // in sequence, for every compiler
    Eigen::MatrixXd cost(rows, cols);
    for (int r = 0; r < cost.rows(); ++r)
      for (int c = 0; c < cost.cols(); ++c) cost(r, c) = forbid(rng) ? kForbidden : value(rng);
    const double gate = trial % 2 ? 2.0 : std::numeric_limits<double>::infinity();
    const auto a = solve_assignment(cost, gate);
    const auto expected = brute_force(cost, gate);
    expect_consistent(a, cost, gate);
    EXPECT_EQ(a.pairs, expected.first) << cost;
    EXPECT_NEAR(a.total_cost, expected.second, 1e-9) << cost;
  }
}

// Costs may be negative (a score to maximise, negated). The most pairs still come first: a very
// negative pair must not win over two ordinary ones when taking it leaves a row unassignable.
TEST(Assignment, NegativeCostsWithForbiddenPairs) {
  Eigen::MatrixXd cost(2, 2);
  cost << -10.0, 0.0, 0.0, kForbidden;
  auto a = solve_assignment(cost);
  EXPECT_EQ(a.pairs, 2);
  EXPECT_THAT(a.row_to_col, ::testing::ElementsAre(1, 0));
  EXPECT_DOUBLE_EQ(a.total_cost, 0.0);

  // Rectangular, all allowed costs negative, NaN and infinity both forbidden.
  Eigen::MatrixXd wide(2, 3);
  wide << -1.0, -5.0, std::numeric_limits<double>::quiet_NaN(), kForbidden, -4.0, -2.0;
  a = solve_assignment(wide);
  EXPECT_EQ(a.pairs, 2);
  EXPECT_THAT(a.row_to_col, ::testing::ElementsAre(1, 2));
  EXPECT_DOUBLE_EQ(a.total_cost, -7.0);

  // Against brute force on random matrices with mixed signs, forbidden pairs and gates.
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<int> size(1, 6);
  std::uniform_real_distribution<double> value(-3.0, 3.0);
  std::bernoulli_distribution forbid(0.3);
  for (int trial = 0; trial < 500; ++trial) {
    const int cols = size(rng), rows = size(rng);  // in sequence, for every compiler
    Eigen::MatrixXd c(rows, cols);
    for (int r = 0; r < c.rows(); ++r)
      for (int k = 0; k < c.cols(); ++k) c(r, k) = forbid(rng) ? kForbidden : value(rng);
    const double gate = trial % 3 == 0 ? std::numeric_limits<double>::infinity() : (trial % 3 == 1 ? 1.0 : -0.5);
    const auto solved = solve_assignment(c, gate);
    const auto expected = brute_force(c, gate);
    expect_consistent(solved, c, gate);
    EXPECT_EQ(solved.pairs, expected.first) << c;
    EXPECT_NEAR(solved.total_cost, expected.second, 1e-9) << c;
  }
}

TEST(Assignment, KnownCases) {
  Eigen::MatrixXd cost(3, 3);
  cost << 4, 1, 3,  //
      2, 0, 5,      //
      3, 2, 2;
  auto a = solve_assignment(cost);
  EXPECT_THAT(a.row_to_col, ::testing::ElementsAre(1, 0, 2));
  EXPECT_DOUBLE_EQ(a.total_cost, 5.0);

  // Rectangular: two detections, one track; the nearer detection wins.
  Eigen::MatrixXd wide(1, 2);
  wide << 0.7, 0.2;
  a = solve_assignment(wide);
  EXPECT_THAT(a.row_to_col, ::testing::ElementsAre(1));
  EXPECT_THAT(a.col_to_row, ::testing::ElementsAre(-1, 0));

  // The gate: nothing within it, nothing assigned.
  Eigen::MatrixXd far(2, 2);
  far << 5, 6, 7, 8;
  a = solve_assignment(far, 1.0);
  EXPECT_EQ(a.pairs, 0);
  EXPECT_THAT(a.row_to_col, ::testing::ElementsAre(-1, -1));

  // More pairs beat a cheaper single pair.
  Eigen::MatrixXd choice(2, 2);
  choice << 0.1, 0.9, 0.9, kForbidden;
  a = solve_assignment(choice);
  EXPECT_EQ(a.pairs, 2);
  EXPECT_THAT(a.row_to_col, ::testing::ElementsAre(1, 0));

  EXPECT_EQ(solve_assignment(Eigen::MatrixXd(0, 3)).pairs, 0);
}

TEST(Lag, FindsAKnownDelay) {
  std::vector<TimedPoint> truth, measured;
  for (int i = 0; i <= 600; ++i) {
    const double t = i / 30.0;
    truth.push_back({t, {std::sin(0.5 * t), 0.5 * std::sin(t), 5.0}});
  }
  for (int i = 0; i <= 600; ++i) {
    const double t = i / 30.0;
    measured.push_back({t, {std::sin(0.5 * (t - 0.15)), 0.5 * std::sin(t - 0.15), 5.0}});
  }
  const auto lag = estimate_lag(truth, measured, 1.0, 0.001);
  ASSERT_TRUE(lag);
  EXPECT_NEAR(*lag, 0.15, 0.002);
  EXPECT_NEAR(*estimate_lag(truth, truth, 1.0, 0.001), 0.0, 1e-9);
  // Motionless curves have no lag to find.
  std::vector<TimedPoint> still(10, TimedPoint{0.0, {1, 1, 1}});
  for (int i = 0; i < 10; ++i) still[static_cast<std::size_t>(i)].t = i;
  EXPECT_FALSE(estimate_lag(still, still));
}

TEST(Lag, InterpolatesLinearlyAndClamps) {
  const std::vector<TimedPoint> truth = {{0.0, {0, 0, 0}}, {1.0, {2, 4, 6}}};
  EXPECT_TRUE(interpolate(truth, 0.25).isApprox(Eigen::Vector3d(0.5, 1, 1.5)));
  EXPECT_TRUE(interpolate(truth, -1).isApprox(Eigen::Vector3d(0, 0, 0)));
  EXPECT_TRUE(interpolate(truth, 3).isApprox(Eigen::Vector3d(2, 4, 6)));
}

TEST(ClearMot, TheThreeFrameExampleOfPyMotmetrics) {
  // py-motmetrics' README: objects 1 and 2, hypotheses 1..3, NaN where a pair may not match.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  ClearMotAccumulator acc;
  Eigen::MatrixXd f0(2, 3);
  f0 << 0.1, nan, 0.3, 0.5, 0.2, 0.3;
  acc.update({1, 2}, {1, 2, 3}, f0);
  Eigen::MatrixXd f1(2, 1);
  f1 << 0.2, 0.4;
  acc.update({1, 2}, {1}, f1);
  Eigen::MatrixXd f2(2, 2);
  f2 << 0.6, 0.2, 0.1, 0.6;
  acc.update({1, 2}, {1, 3}, f2);
  const auto s = acc.summary();
  EXPECT_EQ(s.frames, 3u);
  EXPECT_DOUBLE_EQ(s.mota, 0.5);
  EXPECT_NEAR(s.motp, 0.340, 1e-12);
  EXPECT_NEAR(s.idf1, 0.8333333333333334, 1e-12);
  EXPECT_EQ(s.fp, 1u);
  EXPECT_EQ(s.fn, 1u);
  EXPECT_EQ(s.idsw, 1u);
  EXPECT_EQ(s.fragmentations, 1u);
  EXPECT_EQ(s.matches, 5u);
  EXPECT_EQ(s.mostly_tracked, 1u);     // object 1: 3 of 3
  EXPECT_EQ(s.partially_tracked, 1u);  // object 2: 2 of 3
}

TEST(ClearMot, CrossingTargetsSwapIdentitiesOnce) {
  // Two objects cross; the tracker's hypotheses swap at the crossing and keep the swap.
  ClearMotAccumulator acc;
  for (int k = 0; k < 10; ++k) {
    const double x1 = -1.0 + 0.2 * k, x2 = 1.0 - 0.2 * k;  // they meet between k = 4 and 5
    const double h_a = k < 5 ? x1 : x2, h_b = k < 5 ? x2 : x1;
    Eigen::MatrixXd d(2, 2);
    d << std::abs(x1 - h_a), std::abs(x1 - h_b), std::abs(x2 - h_a), std::abs(x2 - h_b);
    for (int i = 0; i < 4; ++i)
      if (d(i / 2, i % 2) > 0.5) d(i / 2, i % 2) = std::numeric_limits<double>::quiet_NaN();
    acc.update({1, 2}, {10, 20}, d);
  }
  const auto s = acc.summary();
  EXPECT_EQ(s.idsw, 2u);  // both objects change hypothesis at the crossing
  EXPECT_EQ(s.fp, 0u);
  EXPECT_EQ(s.fn, 0u);
  EXPECT_DOUBLE_EQ(s.mota, 1.0 - 2.0 / 20.0);
}

// Every reported CLEAR-MOT key is described in metrics_meta, and only those.
TEST(ClearMot, ReportKeysAndTheirMetaMatch) {
  kestrel::algorithms::MotSummary s;
  s.mota = 0.5;
  s.motp = 0.25;
  s.fragmentations = 3;
  const auto json = kestrel::algorithms::mot_summary_json(s);
  const auto meta = kestrel::algorithms::mot_summary_meta("tracking");
  EXPECT_EQ(json.at("mota"), 0.5);
  EXPECT_EQ(json.at("motp_m"), 0.25);
  EXPECT_EQ(json.at("fragmentations"), 3);
  EXPECT_EQ(json.size(), meta.size());
  for (const auto& [key, value] : json.items()) EXPECT_TRUE(meta.contains("tracking." + key)) << key;
  EXPECT_EQ(meta.at("tracking.mota").at("higher_is_better"), true);
  EXPECT_EQ(meta.at("tracking.motp_m").at("unit"), "m");
  EXPECT_EQ(meta.at("tracking.idsw").at("higher_is_better"), false);
  EXPECT_FALSE(meta.at("tracking.partially_tracked").contains("higher_is_better"));
  EXPECT_TRUE(kestrel::algorithms::mot_summary_meta("").contains("mota"));
}
