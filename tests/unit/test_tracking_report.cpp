// The tracking evaluator's report section: undefined figures are null in report.json and
// "undefined" in report.md, and every value says how to read it (unit, direction).
#include <gmock/gmock.h>

#include "mot_report.hpp"

using namespace kestrel;
using namespace kestrel::evaluation;
using ::testing::HasSubstr;
using ::testing::IsEmpty;

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
  EXPECT_EQ(r.values.at("mota"), 0.0);  // five misses over five objects: defined, and bad
  EXPECT_TRUE(r.values.at("motp_m").is_null());
  EXPECT_TRUE(r.values.at("rmse_m").is_null());
  EXPECT_TRUE(r.values.at("rmse_axes_m").at("y").is_null());
  EXPECT_TRUE(r.values.at("lag_s").is_null());
  EXPECT_EQ(r.values.at("target").at("mota"), 0.0);
  EXPECT_EQ(r.values.at("fn"), 5);
  EXPECT_THAT(r.markdown, HasSubstr("| 5 | 0.0000 | undefined |"));

  // No ground truth at all: MOTA, IDF1 and the target's MOTA have nothing to be measured on.
  const ReportSection empty = tracking_report(TrackingScorer(1.0).summary());
  EXPECT_TRUE(empty.values.at("mota").is_null());
  EXPECT_TRUE(empty.values.at("idf1").is_null());
  EXPECT_TRUE(empty.values.at("target").at("mota").is_null());
  EXPECT_THAT(empty.markdown, HasSubstr("target MOTA undefined"));
}

TEST(TrackingReport, EveryValueHasAUnitAndADirection) {
  const ReportSection r = tracking_report(TrackingScorer(1.0).summary());
  EXPECT_THAT(undescribed_metrics(r), IsEmpty());
  EXPECT_EQ(r.metrics.at("mota").higher_is_better, true);
  EXPECT_EQ(r.metrics.at("rmse_m").unit, "m");
  EXPECT_EQ(r.metrics.at("rmse_m").higher_is_better, false);
  EXPECT_TRUE(r.metrics.at("lag_s").by_magnitude);
  EXPECT_FALSE(r.metrics.at("num_objects").higher_is_better);
}
