// The detection evaluator's report section: undefined figures are null in report.json and
// "undefined" in report.md, and every value says how to read it (unit, direction).
#include <gmock/gmock.h>

#include "detection_report.hpp"

using namespace kestrel::evaluation;
using ::testing::HasSubstr;
using ::testing::Not;

TEST(DetectionReport, NothingDetectedGivesNullsNotPerfectScores) {
  DetectionScorer scorer(1.0);
  for (int i = 0; i < 10; ++i) scorer.add_frame(i / 30.0, i / 30.0, {}, {{1, {0, 0, 5}, true}});
  const ReportSection r = detection_report(scorer.summary());
  EXPECT_TRUE(r.values().at("precision").is_null());
  EXPECT_EQ(r.values().at("recall"), 0.0);
  EXPECT_TRUE(r.values().at("rmse_m").at("x").is_null());
  EXPECT_TRUE(r.values().at("mean_error_m").at("z").is_null());
  EXPECT_TRUE(r.values().at("lag_s").is_null());
  EXPECT_EQ(r.values().at("fn"), 10);
  EXPECT_THAT(r.markdown(), HasSubstr("| 10 | undefined | 0.000 | 0 | 0 | 10 | undefined | undefined | undefined | "
                                      "undefined |"));
  EXPECT_THAT(r.markdown(), Not(HasSubstr("nan")));
}

TEST(DetectionReport, MeasuredFiguresAreBareNumbers) {
  DetectionScorer scorer(1.0);
  scorer.add_frame(0.0, 0.0, {{0.1, 0, 5}, {3, 0, 5}}, {{1, {0, 0, 5}, true}});
  const ReportSection r = detection_report(scorer.summary());
  EXPECT_EQ(r.values().at("precision"), 0.5);
  EXPECT_EQ(r.values().at("recall"), 1.0);
  EXPECT_NEAR(r.values().at("rmse_m").at("x").get<double>(), 0.1, 1e-12);
  EXPECT_THAT(r.markdown(), HasSubstr("| 1 | 0.500 | 1.000 | 1 | 1 | 0 | 0.100 | 0.000 | 0.000 |"));
}

// The paper's Table 1 gives its errors in the body frame (FLU: x forward = depth, y left, z up).
// Detections 0.1 m right, 0.2 m low and 0.3 m far of the truth (camera frame) are, in body axes,
// 0.3 m forward, 0.1 m right (y = -0.1) and 0.2 m low (z = -0.2).
TEST(DetectionReport, BodyFrameFiguresAreTheCameraFiguresOnThePapersAxes) {
  DetectionScorer scorer(1.0);
  scorer.add_frame(0.0, 0.0, {{0.1, 0.2, 5.3}}, {{1, {0, 0, 5}, true}});
  const ReportSection r = detection_report(scorer.summary());
  const auto& rmse = r.values().at("rmse_body_m");
  EXPECT_NEAR(rmse.at("x").get<double>(), 0.3, 1e-12);
  EXPECT_NEAR(rmse.at("y").get<double>(), 0.1, 1e-12);
  EXPECT_NEAR(rmse.at("z").get<double>(), 0.2, 1e-12);
  const auto& bias = r.values().at("bias_body_m");
  EXPECT_NEAR(bias.at("x").get<double>(), 0.3, 1e-12);
  EXPECT_NEAR(bias.at("y").get<double>(), -0.1, 1e-12);
  EXPECT_NEAR(bias.at("z").get<double>(), -0.2, 1e-12);
  EXPECT_THAT(r.markdown(), HasSubstr("body axes (FLU: x forward = depth, y left, z up; the paper's Table 1): RMSE "
                                      "x 0.300, y 0.100, z 0.200 m; bias x +0.300 m, y -0.100 m, z -0.200 m"));
  const ReportSection none = detection_report(DetectionScorer(1.0).summary());
  EXPECT_TRUE(none.values().at("rmse_body_m").at("x").is_null());
  EXPECT_TRUE(none.values().at("bias_body_m").at("z").is_null());
}

TEST(DetectionReport, EveryValueHasAUnitAndADirection) {
  const std::vector<std::string> keys = {"tp",     "fp",    "fn",           "frames",      "precision",  "recall",
                                         "rmse_m", "lag_s", "mean_error_m", "rmse_body_m", "bias_body_m"};
  for (const auto& summary : {DetectionScorer(1.0).summary(), [] {
                                DetectionScorer s(1.0);
                                s.add_frame(0.0, 0.0, {{0.1, 0, 5}}, {{1, {0, 0, 5}, true}});
                                return s.summary();
                              }()}) {
    const ReportSection r = detection_report(summary);
    for (const auto& key : keys) EXPECT_TRUE(r.metrics().count(key)) << key;
  }
  const ReportSection r = detection_report(DetectionScorer(1.0).summary());
  EXPECT_EQ(r.metrics().at("precision").higher_is_better, true);
  EXPECT_EQ(r.metrics().at("rmse_m").unit, "m");
  EXPECT_EQ(r.metrics().at("rmse_m").higher_is_better, false);
  EXPECT_TRUE(r.metrics().at("lag_s").by_magnitude);
  EXPECT_EQ(r.metrics().at("lag_s").unit, "s");
  EXPECT_FALSE(r.metrics().at("frames").higher_is_better);  // a count: neither way is better
}
