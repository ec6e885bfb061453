// The foreground segmentation of stereo_depth on disparity maps whose answer is known: a drone's
// silhouette a metre in front of a canopy, a trunk, a wall, the ground's slope, holes and noise.
#include <gmock/gmock.h>

#include <opencv2/imgproc.hpp>
#include <random>

#include "foreground_mask.hpp"

using namespace kestrel;
using namespace kestrel::stereo;

namespace {

// The paper's camera: fx = 304 px at 640 px, b = 0.12 m, so fx b = 36.5 px m.
msg::StereoCalibration mask_calibration() {
  msg::StereoCalibration c;
  c.fx = c.fy = 304.0;
  c.baseline_m = 0.12;
  return c;
}

double disparity_at(double depth_m) { return 304.0 * 0.12 / depth_m; }

// A CV_16S disparity map (1/16 px) of a surface at `depth_m` everywhere.
cv::Mat surface(double depth_m) { return cv::Mat(480, 640, CV_16S, cv::Scalar(disparity_at(depth_m) * 16.0)); }

void paint(cv::Mat& disparity16, const cv::Rect& r, double depth_m) {
  disparity16(r).setTo(cv::Scalar(depth_m > 0 ? disparity_at(depth_m) * 16.0 : -16.0));
}

int count(const cv::Mat& mask, const cv::Rect& r) { return cv::countNonZero(mask(r)); }

ForegroundOptions options() {
  ForegroundOptions o;
  o.gap_m = 0.5;
  return o;
}

}  // namespace

TEST(ForegroundMask, ADroneAMetreInFrontOfACanopyStandsOutAndTheCanopyDoesNot) {
  cv::Mat d = surface(6.0);
  const cv::Rect drone(300, 230, 38, 12);  // 0.63 x 0.2 m at 5 m
  paint(d, drone, 5.0);
  const cv::Mat mask = foreground_mask(d, mask_calibration(), options());
  EXPECT_EQ(count(mask, drone), drone.area());
  EXPECT_EQ(cv::countNonZero(mask), drone.area());
}

TEST(ForegroundMask, ObjectsTallerOrWiderThanTheLimitsAreBackground) {
  cv::Mat d = surface(10.0);
  const cv::Rect trunk(100, 150, 15, 150);  // 0.35 m wide, 3.5 m tall at 7 m
  const cv::Rect wall(300, 200, 200, 20);   // 4.6 m wide, 0.46 m tall at 7 m
  paint(d, trunk, 7.0);
  paint(d, wall, 7.0);
  const cv::Mat mask = foreground_mask(d, mask_calibration(), options());
  EXPECT_EQ(cv::countNonZero(mask), 0);
  // The same trunk, cut to 0.3 m, is an object.
  cv::Mat short_trunk = surface(10.0);
  paint(short_trunk, {100, 150, 15, 13}, 7.0);
  EXPECT_EQ(cv::countNonZero(foreground_mask(short_trunk, mask_calibration(), options())), 15 * 13);
}

TEST(ForegroundMask, ALessThanTheGapOrTheMinimumStepInFrontIsBackground) {
  cv::Mat d = surface(6.0);
  paint(d, {300, 230, 38, 12}, 5.7);  // 0.3 m in front
  EXPECT_EQ(cv::countNonZero(foreground_mask(d, mask_calibration(), options())), 0);
  // 1 m in front of a surface at 9.5 m is 0.36 px: a full metre, yet under the 0.5 px step.
  cv::Mat far = surface(9.5);
  paint(far, {300, 230, 24, 12}, 8.5);
  EXPECT_EQ(cv::countNonZero(foreground_mask(far, mask_calibration(), options())), 0);
  ForegroundOptions fine = options();
  fine.min_step_px = 0.2;
  EXPECT_EQ(cv::countNonZero(foreground_mask(far, mask_calibration(), fine)), 24 * 12);
}

TEST(ForegroundMask, TheGroundsSlopeIsNotForeground) {
  // A camera 2 m above flat ground: row v below the horizon sees it at disparity b (v - cy) / h.
  cv::Mat d(480, 640, CV_16S, cv::Scalar(-16));
  for (int v = 241; v < 480; ++v) d.row(v).setTo(cv::Scalar(0.12 * (v - 240) / 2.0 * 16.0));
  EXPECT_EQ(cv::countNonZero(foreground_mask(d, mask_calibration(), options())), 0);
}

TEST(ForegroundMask, AgainstTheUnmatchedSkyAnObjectStandsOut) {
  cv::Mat d(480, 640, CV_16S, cv::Scalar(-16));  // nothing matched: the sky
  const cv::Rect drone(300, 100, 25, 8);         // at 7.5 m
  paint(d, drone, 7.5);
  const cv::Mat mask = foreground_mask(d, mask_calibration(), options());
  EXPECT_EQ(count(mask, drone), drone.area());
}

TEST(ForegroundMask, AHoleInASurfaceIsNotAViewThroughIt) {
  // A trunk 0.9 m tall at 7 m, in front of a surface at 10 m, with unmatched rows across its middle.
  cv::Mat d = surface(10.0);
  paint(d, {100, 200, 15, 40}, 7.0);
  paint(d, {100, 218, 15, 4}, -1.0);
  EXPECT_EQ(cv::countNonZero(foreground_mask(d, mask_calibration(), options())), 0);
  // Taken as a view of the sky, the hole cuts the trunk into two objects short enough to stand out.
  ForegroundOptions o = options();
  o.max_hole_px = 0;
  EXPECT_GT(cv::countNonZero(foreground_mask(d, mask_calibration(), o)), 0);
}

TEST(ForegroundMask, SliversThinnerThanTheMinimumThicknessGo) {
  cv::Mat d = surface(6.0);
  paint(d, {100, 100, 3, 12}, 5.0);  // a sliver 3 px wide
  paint(d, {300, 230, 20, 10}, 5.0);
  const cv::Mat mask = foreground_mask(d, mask_calibration(), options());
  EXPECT_EQ(cv::countNonZero(mask), 20 * 10);
}

TEST(ForegroundMask, NoiseOnASurfaceDoesNotStandOut) {
  cv::Mat d = surface(6.0);
  cv::Mat noise(d.size(), CV_16S);
  cv::RNG rng(7);
  rng.fill(noise, cv::RNG::NORMAL, 0.0, 0.1 * 16.0);  // 0.1 px of matching noise
  d += noise;
  EXPECT_EQ(cv::countNonZero(foreground_mask(d, mask_calibration(), options())), 0);
}

TEST(VerticalMorphology, MatchesABruteForceMinimumAndMaximum) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> value(0.0f, 10.0f);
  for (int radius : {1, 2, 5, 17}) {
    cv::Mat image(37, 9, CV_32F);
    for (int v = 0; v < image.rows; ++v)
      for (int u = 0; u < image.cols; ++u) image.at<float>(v, u) = value(rng);
    const cv::Mat eroded = vertical_erode(image, radius), dilated = vertical_dilate(image, radius);
    for (int v = 0; v < image.rows; ++v)
      for (int u = 0; u < image.cols; ++u) {
        float lo = image.at<float>(v, u), hi = lo;
        for (int w = std::max(0, v - radius); w <= std::min(image.rows - 1, v + radius); ++w) {
          lo = std::min(lo, image.at<float>(w, u));
          hi = std::max(hi, image.at<float>(w, u));
        }
        ASSERT_EQ(eroded.at<float>(v, u), lo) << "radius " << radius << " at " << v << "," << u;
        ASSERT_EQ(dilated.at<float>(v, u), hi) << "radius " << radius << " at " << v << "," << u;
      }
  }
}

TEST(ShortHoles, AreFilledWithTheFartherOfTheirEndsAndLongRunsStay) {
  cv::Mat column = (cv::Mat_<float>(10, 1) << 5, 0, 0, 4, 0, 0, 0, 0, 0, 3);
  fill_short_holes_down(column, 2);
  const cv::Mat expected = (cv::Mat_<float>(10, 1) << 5, 4, 4, 4, 0, 0, 0, 0, 0, 3);
  EXPECT_EQ(cv::norm(column, expected, cv::NORM_INF), 0.0);
}

TEST(ForegroundMask, TheColumnsTheRightCameraDoesNotSeeAreOutsideThePicture) {
  // A matcher with 80 disparities leaves the 80 leftmost columns unmatched. A canopy 0.5 m tall at
  // 6 m, in front of a surface at 10 m, that starts at column 80 and runs 30 columns may go on
  // beyond the picture: it is not judged against that band.
  cv::Mat d = surface(10.0);
  paint(d, {0, 0, 80, 480}, -1.0);
  paint(d, {80, 200, 30, 25}, 6.0);
  ForegroundOptions o = options();
  o.unseen_left_columns = 80;
  EXPECT_EQ(cv::countNonZero(foreground_mask(d, mask_calibration(), o)), 0);
  // Taken as a view of the sky, the band makes it an object.
  o.unseen_left_columns = 0;
  EXPECT_EQ(cv::countNonZero(foreground_mask(d, mask_calibration(), o)), 30 * 25);
  // The same piece away from the band is one.
  cv::Mat away = surface(10.0);
  paint(away, {0, 0, 80, 480}, -1.0);
  paint(away, {200, 200, 30, 25}, 6.0);
  o.unseen_left_columns = 80;
  EXPECT_EQ(cv::countNonZero(foreground_mask(away, mask_calibration(), o)), 30 * 25);
}
