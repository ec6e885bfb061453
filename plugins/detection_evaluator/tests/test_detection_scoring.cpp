// The detection evaluator's scoring on hand-made sequences with known answers.
#include <gmock/gmock.h>

#include "detection_scoring.hpp"

using namespace kestrel::evaluation;

TEST(DetectionScorer, CountsHitsFalseAlarmsAndMisses) {
  DetectionScorer scorer(1.0);
  const std::vector<TruthObject> one = {{1, {0, 0, 5}, true}};
  // Frame 1: a hit 0.1 m off in x and a false alarm far away.
  auto f = scorer.add_frame(0.0, 0.0, {{0.1, 0, 5}, {3, 0, 5}}, one);
  EXPECT_EQ(f.tp, 1);
  EXPECT_EQ(f.fp, 1);
  EXPECT_EQ(f.fn, 0);
  // Frame 2: nothing detected: a miss. Frame 3: a detection 1.5 m away: outside the gate.
  scorer.add_frame(0.1, 0.1, {}, one);
  f = scorer.add_frame(0.2, 0.2, {{1.5, 0, 5}}, one);
  EXPECT_EQ(f.fp, 1);
  EXPECT_EQ(f.fn, 1);
  // Frame 4: hit 0.3 m off in y and -0.2 in z.
  scorer.add_frame(0.3, 0.3, {{0, 0.3, 4.8}}, one);
  // Frame 5: the object is out of view and undetected: not a miss.
  scorer.add_frame(0.4, 0.4, {}, {{1, {0, 0, 20}, false}});
  const auto s = scorer.summary();
  EXPECT_EQ(s.frames, 5u);
  EXPECT_EQ(s.tp, 2u);
  EXPECT_EQ(s.fp, 2u);
  EXPECT_EQ(s.fn, 2u);
  EXPECT_DOUBLE_EQ(*s.precision, 0.5);
  EXPECT_DOUBLE_EQ(*s.recall, 0.5);
  EXPECT_NEAR(s.rmse->x(), std::sqrt((0.01 + 0.0) / 2), 1e-12);
  EXPECT_NEAR(s.rmse->y(), std::sqrt((0.0 + 0.09) / 2), 1e-12);
  EXPECT_NEAR(s.rmse->z(), std::sqrt((0.0 + 0.04) / 2), 1e-12);
  EXPECT_NEAR(s.mean_error->z(), -0.1, 1e-12);
}

TEST(DetectionScorer, HungarianPairsTwoObjectsOptimally) {
  DetectionScorer scorer(1.0);
  // Greedy would give detection 0 to object 1 (0.4 m) and leave object 2 beyond the gate;
  // the optimal assignment matches both.
  const auto f = scorer.add_frame(0, 0, {{0.6, 0, 5}, {-0.2, 0, 5}}, {{1, {0.2, 0, 5}, true}, {2, {1.5, 0, 5}, true}});
  EXPECT_EQ(f.tp, 2);
  EXPECT_EQ(f.fp, 0);
  EXPECT_EQ(f.fn, 0);
}

TEST(DetectionScorer, LagOfDelayedDetections) {
  DetectionScorer scorer(1.0);
  // Detections reach the evaluator 0.15 s after capture: the lag is 0.15 s.
  for (int i = 0; i < 300; ++i) {
    const double t = i / 30.0;
    const Eigen::Vector3d p(std::sin(0.5 * t), 0.5 * std::sin(t), 5.0);
    scorer.add_frame(t, t + 0.15, {p}, {{1, p, true}});
  }
  const auto s = scorer.summary(1.0, 0.001);
  ASSERT_TRUE(s.lag_s);
  EXPECT_NEAR(*s.lag_s, 0.15, 0.002);
  EXPECT_DOUBLE_EQ(*s.recall, 1.0);
  EXPECT_NEAR(s.rmse->norm(), 0.0, 1e-12);
}

TEST(DetectionScorer, WhatThereIsNothingToMeasureOnIsUndefined) {
  const auto empty = DetectionScorer(1.0).summary();
  EXPECT_FALSE(empty.precision);
  EXPECT_FALSE(empty.recall);
  EXPECT_FALSE(empty.rmse);
  EXPECT_FALSE(empty.mean_error);
  EXPECT_FALSE(empty.lag_s);
  // An intruder in view that is never detected: recall 0, but no precision and no error.
  DetectionScorer missed(1.0);
  missed.add_frame(0.0, 0.0, {}, {{1, {0, 0, 5}, true}});
  const auto m = missed.summary();
  EXPECT_FALSE(m.precision);
  EXPECT_DOUBLE_EQ(*m.recall, 0.0);
  EXPECT_FALSE(m.rmse);
  // Only false alarms: precision 0, and still no error.
  DetectionScorer clutter(1.0);
  clutter.add_frame(0.0, 0.0, {{4, 0, 5}}, {{1, {0, 0, 5}, false}});
  const auto c = clutter.summary();
  EXPECT_DOUBLE_EQ(*c.precision, 0.0);
  EXPECT_FALSE(c.recall);
  EXPECT_FALSE(c.rmse);
}

TEST(DetectionScorer, FramesCapturedBeforeSkipFirstAreNotScored) {
  DetectionScorer scorer(1.0, /*skip_first_s=*/0.5);
  const std::vector<TruthObject> one = {{1, {0, 0, 5}, true}};
  // Before 0.5 s: a false alarm, a miss and a large error, none of which may count.
  for (const double t : {0.0, 0.25, 0.4999}) {
    const auto f = scorer.add_frame(t, t, {{0.9, 0, 5}, {3, 0, 5}}, t < 0.3 ? one : std::vector<TruthObject>{});
    EXPECT_FALSE(f.scored) << t;
    EXPECT_EQ(f.tp + f.fp + f.fn, 0) << t;
    EXPECT_TRUE(f.matches.empty()) << t;
  }
  scorer.add_frame(0.3, 0.3, {}, one);  // a miss, also too early
  // From 0.5 s on (inclusive): scored.
  const auto at = scorer.add_frame(0.5, 0.5, {{0.1, 0, 5}}, one);
  EXPECT_TRUE(at.scored);
  EXPECT_EQ(at.tp, 1);
  scorer.add_frame(0.6, 0.6, {{0, 0.2, 5}}, one);
  scorer.add_frame(0.7, 0.7, {{0, 0, 5.3}}, one);
  const auto s = scorer.summary();
  EXPECT_EQ(s.frames, 3u);
  EXPECT_EQ(s.tp, 3u);
  EXPECT_EQ(s.fp, 0u);
  EXPECT_EQ(s.fn, 0u);
  EXPECT_NEAR(s.rmse->x(), std::sqrt(0.01 / 3), 1e-12);
  EXPECT_NEAR(s.rmse->y(), std::sqrt(0.04 / 3), 1e-12);
  EXPECT_NEAR(s.rmse->z(), std::sqrt(0.09 / 3), 1e-12);
}
