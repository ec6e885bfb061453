// Coarse-to-fine matching of the regions that stand out, on scenes whose answer is known: the
// regions a coarse mask gives, a region matched over its own disparities, and the whole pipeline
// against matching everything at full resolution.
#include <gmock/gmock.h>

#include <opencv2/imgproc.hpp>

#include "depth_pipeline.hpp"
#include "kestrel/error.hpp"

using namespace kestrel;
using namespace kestrel::stereo;

namespace {

// The paper's camera at 640x480: fx 304 px, b 0.12 m.
msg::StereoCalibration region_calibration() {
  msg::StereoCalibration c;
  c.width = 640;
  c.height = 480;
  c.fx = c.fy = 304.0;
  c.cx = 320.0;
  c.cy = 240.0;
  c.baseline_m = 0.12;
  return c;
}

// A textured wall at disparity 4 (9.1 m) with a textured box of 48 x 20 px in front of it at
// disparity 22 (1.66 m): a small object a long way in front of its background.
const cv::Rect kBox(300, 200, 48, 20);
constexpr int kBoxDisparity = 22;

std::pair<cv::Mat, cv::Mat> box_in_front_of_a_wall() {
  cv::RNG rng(11);
  cv::Mat wall(480, 644, CV_8U), box(kBox.height, kBox.width, CV_8U);
  rng.fill(wall, cv::RNG::UNIFORM, 0, 255);
  rng.fill(box, cv::RNG::UNIFORM, 0, 255);
  cv::GaussianBlur(wall, wall, cv::Size(5, 5), 0);
  cv::GaussianBlur(box, box, cv::Size(3, 3), 0);
  cv::Mat left = wall(cv::Rect(0, 0, 640, 480)).clone(), right = wall(cv::Rect(4, 0, 640, 480)).clone();
  box.copyTo(left(kBox));
  box.copyTo(right(kBox - cv::Point(kBoxDisparity, 0)));  // right(u - d) = left(u)
  return {left, right};
}

MatcherOptions paper_matcher() {
  MatcherOptions o;
  o.num_disparities = 80;
  return o;
}

ForegroundOptions paper_foreground() {
  ForegroundOptions o;
  o.gap_m = 0.5;
  return o;
}

DepthOptions coarse_to_fine() {
  DepthOptions o;
  o.downscale = 2;
  o.fine_regions = true;
  return o;
}

// Points whose pixel lies in `r` (grown by `grow`), by projecting them back.
std::size_t points_in(const pcl::PointCloud<pcl::PointXYZ>& cloud, cv::Rect r, int grow) {
  const msg::StereoCalibration c = region_calibration();
  r = cv::Rect(r.x - grow, r.y - grow, r.width + 2 * grow, r.height + 2 * grow);
  std::size_t n = 0;
  for (const auto& p : cloud)
    if (r.contains(cv::Point(static_cast<int>(std::lround(c.fx * p.x / p.z + c.cx)),
                             static_cast<int>(std::lround(c.fy * p.y / p.z + c.cy)))))
      ++n;
  return n;
}

}  // namespace

TEST(FineRegions, EachCoarseObjectBecomesAFullResolutionBoxWithAMargin) {
  cv::Mat mask(240, 320, CV_8U, cv::Scalar(0));
  mask(cv::Rect(100, 50, 10, 4)).setTo(255);
  mask(cv::Rect(250, 150, 6, 6)).setTo(255);
  mask.at<std::uint8_t>(55, 110) = 255;  // touches the first object's corner: part of it
  const auto boxes = fine_regions(mask, 2, {640, 480}, 8);
  ASSERT_EQ(boxes.size(), 2u);
  EXPECT_EQ(boxes[0], cv::Rect(200 - 8, 100 - 8, 22 + 16, 12 + 16));
  EXPECT_EQ(boxes[1], cv::Rect(500 - 8, 300 - 8, 12 + 16, 12 + 16));
}

TEST(FineRegions, OverlappingBoxesAreMergedAndStayInsideTheImage) {
  cv::Mat mask(240, 320, CV_8U, cv::Scalar(0));
  mask(cv::Rect(0, 0, 5, 5)).setTo(255);  // in the corner: the margin is cut at the image's edge
  mask(cv::Rect(7, 2, 5, 5)).setTo(255);  // 2 coarse px away: the margins overlap
  mask(cv::Rect(315, 235, 5, 5)).setTo(255);
  const auto boxes = fine_regions(mask, 2, {640, 480}, 8);
  ASSERT_EQ(boxes.size(), 2u);
  EXPECT_EQ(boxes[0], cv::Rect(0, 0, 24 + 8, 14 + 8));
  EXPECT_EQ(boxes[1], cv::Rect(630 - 8, 470 - 8, 18, 18));
}

TEST(FineRegions, ARegionMatchedAloneIsWhatMatchingTheWholePairGivesThere) {
  const auto [left, right] = box_in_front_of_a_wall();
  const cv::Rect region(kBox.x - 8, kBox.y - 8, kBox.width + 16, kBox.height + 16);
  const cv::Mat alone = match_region(grey_pair(left, right), region, paper_matcher());
  ASSERT_EQ(alone.size(), region.size());
  const cv::Mat whole = compute_disparity(*make_matcher(paper_matcher()), left, right)(region);
  EXPECT_LE(cv::countNonZero(alone != whole), region.area() / 100);
  // The box at its disparity, the wall above it at the wall's.
  EXPECT_NEAR(alone.at<short>(18, 30) / 16.0, kBoxDisparity, 0.5);
  EXPECT_NEAR(alone.at<short>(2, 30) / 16.0, 4.0, 0.5);  // above it (beside it, on its left, the wall is hidden)
}

TEST(DepthPipeline, CoarseToFineGivesTheFullResolutionObjectAndNothingElse) {
  const auto [left, right] = box_in_front_of_a_wall();
  DepthPipeline full(paper_matcher(), paper_foreground(), DepthOptions{});
  DepthPipeline fine(paper_matcher(), paper_foreground(), coarse_to_fine());
  const DepthResult a = full.compute(left, right, region_calibration());
  const DepthResult b = fine.compute(left, right, region_calibration());
  EXPECT_EQ(b.regions, 1);
  EXPECT_EQ(b.pixels_per_point, 1);
  EXPECT_DOUBLE_EQ(b.focal_baseline_px_m, 304.0 * 0.12);
  EXPECT_LT(b.region_pixels, 640u * 480u / 50u);
  // Every point is the box's, at its depth, and there are as many as at full resolution.
  ASSERT_GT(a.points->size(), static_cast<std::size_t>(kBox.area() / 2));
  EXPECT_EQ(points_in(*b.points, kBox, 2), b.points->size());
  EXPECT_NEAR(static_cast<double>(b.points->size()), static_cast<double>(a.points->size()),
              0.05 * static_cast<double>(a.points->size()));
  for (const auto& p : *b.points) EXPECT_NEAR(p.z, 304.0 * 0.12 / kBoxDisparity, 0.05);
  // Coarse alone gives a quarter as many points, each standing for 2 x 2 pixels.
  DepthOptions coarse = coarse_to_fine();
  coarse.fine_regions = false;
  const DepthResult c =
      DepthPipeline(paper_matcher(), paper_foreground(), coarse).compute(left, right, region_calibration());
  EXPECT_EQ(c.pixels_per_point, 2);
  EXPECT_LT(c.points->size(), b.points->size() / 2);
}

TEST(DepthPipeline, FineRegionsNeedACoarseMatchAndTheSegmentation) {
  DepthOptions no_coarse = coarse_to_fine();
  no_coarse.downscale = 1;
  EXPECT_THROW(DepthPipeline(paper_matcher(), paper_foreground(), no_coarse), Error);
  EXPECT_THROW(DepthPipeline(paper_matcher(), ForegroundOptions{}, coarse_to_fine()), Error);
}

TEST(FineRegions, LeavesTheCoarseMatchMissedAreTheirOwnBackground) {
  // The coarse match found nothing (a canopy's fine leaves, blurred away at half resolution), so
  // its background is the sky. At full resolution the region's crop holds the canopy at 6.1 m
  // (disparity 6) and a drone of 30 x 10 px at 5 m (7.3) in front of it.
  const cv::Mat coarse_map(240, 320, CV_32F, cv::Scalar(0.0f));
  const DisparityBackground coarse(coarse_map, region_calibration(), paper_foreground());
  cv::Mat crop(120, 200, CV_32F, cv::Scalar(6.0f));
  const cv::Rect drone(90, 55, 30, 10);
  crop(drone).setTo(7.3f);
  const cv::Rect box(20, 16, 170, 100);
  const cv::Point origin(400, 200);
  const double fb = 304.0 * 0.12;
  const DisparityBackground own(crop, region_calibration(), paper_foreground());

  const cv::Mat judged = region_foreground(crop, box, origin, 2, coarse, &own, fb, paper_foreground());
  ASSERT_EQ(judged.size(), box.size());
  EXPECT_EQ(cv::countNonZero(judged), drone.area());
  EXPECT_EQ(cv::countNonZero(judged(drone - box.tl())), drone.area());
  // Against the coarse background alone every leaf stands out of the sky.
  const cv::Mat coarse_only = region_foreground(crop, box, origin, 2, coarse, nullptr, fb, paper_foreground());
  EXPECT_EQ(cv::countNonZero(coarse_only), box.area());
}
