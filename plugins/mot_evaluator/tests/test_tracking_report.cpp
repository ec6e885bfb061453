// The tracking evaluator's report section: undefined figures are null in report.json and
// "undefined" in report.md, and every value says how to read it (unit, direction).
#include <gmock/gmock.h>

#include "mot_report.hpp"

using namespace kestrel;
using namespace kestrel::evaluation;
using ::testing::HasSubstr;

namespace {

msg::GroundTruth truth_at(double t, const Eigen::Vector3d& p) {
  msg::GroundTruth truth;
  truth.stamp = from_seconds(t);
  msg::GroundTruthObject o;
  o.id = 1;
  o.position_camera = p;
  o.in_view = true;
  truth.objects.push_back(o);
  return truth;
}

}  // namespace

TEST(TrackingReport, NoTracksGiveNullsNotPerfectOrZeroScores) {
  TrackingScorer scorer(1.0);
  for (int i = 0; i < 5; ++i) {
    msg::Tracks none;
    none.stamp = from_seconds(i / 30.0);
    scorer.add_frame(none, truth_at(i / 30.0, {0, 0, 5}), i / 30.0);
  }
  const ReportSection r = tracking_report(scorer.summary());
  EXPECT_EQ(r.values().at("mota"), 0.0);  // five misses over five objects: defined, and bad
  EXPECT_TRUE(r.values().at("motp_m").is_null());
  EXPECT_TRUE(r.values().at("rmse_m").is_null());
  EXPECT_TRUE(r.values().at("rmse_axes_m").at("y").is_null());
  EXPECT_TRUE(r.values().at("lag_s").is_null());
  EXPECT_EQ(r.values().at("target").at("mota"), 0.0);
  EXPECT_EQ(r.values().at("fn"), 5);
  EXPECT_THAT(r.markdown(), HasSubstr("| 5 | 0.0000 | undefined |"));

  // No ground truth at all: MOTA, IDF1 and the target's MOTA have nothing to be measured on.
  const ReportSection empty = tracking_report(TrackingScorer(1.0).summary());
  EXPECT_TRUE(empty.values().at("mota").is_null());
  EXPECT_TRUE(empty.values().at("idf1").is_null());
  EXPECT_TRUE(empty.values().at("target").at("mota").is_null());
  EXPECT_THAT(empty.markdown(), HasSubstr("target MOTA undefined"));
}

TEST(TrackingReport, EveryValueHasAUnitAndADirection) {
  const ReportSection r = tracking_report(TrackingScorer(1.0).summary());
  EXPECT_EQ(r.metrics().at("mota").higher_is_better, true);
  EXPECT_EQ(r.metrics().at("rmse_m").unit, "m");
  EXPECT_EQ(r.metrics().at("rmse_m").higher_is_better, false);
  EXPECT_TRUE(r.metrics().at("lag_s").by_magnitude);
  EXPECT_FALSE(r.metrics().at("num_objects").higher_is_better);
}

// The selected track 0.2 m right of, 0.05 m below and 0.1 m nearer than the intruder (camera
// frame), every frame: in the body axes of the paper's Table 1 that is 0.1 m short (x = -0.1),
// 0.2 m right (y = -0.2) and 0.05 m low (z = -0.05).
TEST(TrackingReport, BodyFrameFiguresAreTheCameraFiguresOnThePapersAxes) {
  TrackingScorer scorer(1.0);
  for (int i = 0; i < 5; ++i) {
    msg::Tracks tracks;
    tracks.stamp = from_seconds(i / 30.0);
    msg::Track t;
    t.id = 7;
    t.state = Eigen::VectorXd::Zero(9);
    t.state.head<3>() = Eigen::Vector3d(0.2, 0.05, 4.9);
    tracks.items.push_back(t);
    tracks.selected_id = 7;
    scorer.add_frame(tracks, truth_at(i / 30.0, {0, 0, 5}), i / 30.0);
  }
  const ReportSection r = tracking_report(scorer.summary());
  EXPECT_NEAR(r.values().at("rmse_body_m").at("x").get<double>(), 0.1, 1e-9);
  EXPECT_NEAR(r.values().at("rmse_body_m").at("y").get<double>(), 0.2, 1e-9);
  EXPECT_NEAR(r.values().at("rmse_body_m").at("z").get<double>(), 0.05, 1e-9);
  EXPECT_NEAR(r.values().at("bias_body_m").at("x").get<double>(), -0.1, 1e-9);
  EXPECT_NEAR(r.values().at("bias_body_m").at("y").get<double>(), -0.2, 1e-9);
  EXPECT_NEAR(r.values().at("bias_body_m").at("z").get<double>(), -0.05, 1e-9);
  EXPECT_THAT(r.markdown(), HasSubstr("RMSE x 0.100, y 0.200, z 0.050 m; bias x -0.100, y -0.200, z -0.050 m"));
}
