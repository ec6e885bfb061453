// Stereo matching and the paper's equation (1) on inputs whose answer is known.
#include <gmock/gmock.h>

#include <opencv2/imgproc.hpp>
#include <random>

#include "kestrel/error.hpp"
#include "stereo_matching.hpp"

using namespace kestrel;
using namespace kestrel::stereo;

namespace {

msg::StereoCalibration calibration() {
  msg::StereoCalibration c;
  c.width = 640;
  c.height = 480;
  c.fx = c.fy = 452.0;
  c.cx = 320.0;
  c.cy = 240.0;
  c.baseline_m = 0.12;
  return c;
}

// A random texture seen by the right camera `shift` pixels further left (right(u - shift) =
// left(u)): a fronto-parallel plane at depth f b / shift.
std::pair<cv::Mat, cv::Mat> shifted_pair(int shift) {
  cv::Mat wide(480, 640 + shift, CV_8U);
  cv::randu(wide, 0, 255);
  cv::GaussianBlur(wide, wide, cv::Size(3, 3), 0);
  return {wide(cv::Rect(0, 0, 640, 480)).clone(), wide(cv::Rect(shift, 0, 640, 480)).clone()};
}

}  // namespace

TEST(Reprojection, KnownDisparityGivesEquationOne) {
  cv::Mat disparity(480, 640, CV_16S, cv::Scalar(-16));
  disparity.at<short>(240, 320) = 16 * 10;  // d = 10 px at the principal point
  disparity.at<short>(100, 500) = 16 * 20;  // d = 20 px off-centre
  disparity.at<short>(10, 10) = 8;          // d = 0.5 px: Z = 108 m, beyond max depth
  const auto cloud = reproject(disparity, calibration(), 0.5, 15.0);
  ASSERT_EQ(cloud->size(), 2u);
  // Z = f b / d, X = b (u - cx) / d, Y = b (v - cy) / d.
  EXPECT_NEAR((*cloud)[0].x, 0.12 * (500 - 320) / 20.0, 1e-6);
  EXPECT_NEAR((*cloud)[0].y, 0.12 * (100 - 240) / 20.0, 1e-6);
  EXPECT_NEAR((*cloud)[0].z, 452.0 * 0.12 / 20.0, 1e-5);
  EXPECT_NEAR((*cloud)[1].x, 0.0, 1e-9);
  EXPECT_NEAR((*cloud)[1].y, 0.0, 1e-9);
  EXPECT_NEAR((*cloud)[1].z, 452.0 * 0.12 / 10.0, 1e-5);
}

// Non-square pixels (fx != fy): disparity is measured along x, so depth takes fx, and a pixel's
// row offset becomes metres through fy. Points placed in front of the camera and projected with
// the pinhole model come back where they were.
TEST(Reprojection, NonSquarePixelsUseFyForTheRows) {
  msg::StereoCalibration c = calibration();
  c.fx = 400.0;
  c.fy = 300.0;
  const std::vector<Eigen::Vector3d> points = {{0.6, -0.48, 4.8}, {-0.96, 0.72, 2.4}};
  cv::Mat disparity(480, 640, CV_16S, cv::Scalar(-16));
  for (const auto& p : points) {
    const double u = c.cx + c.fx * p.x() / p.z(), v = c.cy + c.fy * p.y() / p.z();
    const double d = c.fx * c.baseline_m / p.z();
    ASSERT_DOUBLE_EQ(u, std::round(u));
    ASSERT_DOUBLE_EQ(v, std::round(v));
    disparity.at<short>(static_cast<int>(v), static_cast<int>(u)) = static_cast<short>(std::lround(16 * d));
  }
  const auto cloud = reproject(disparity, c, 0.5, 15.0);
  ASSERT_EQ(cloud->size(), 2u);
  // The cloud is in row order: the second point (v = 330) comes after the first (v = 210).
  for (std::size_t i = 0; i < 2; ++i) {
    const Eigen::Vector3d& p = points[i];
    EXPECT_NEAR((*cloud)[i].x, p.x(), 1e-6) << i;
    EXPECT_NEAR((*cloud)[i].y, p.y(), 1e-6) << i;
    EXPECT_NEAR((*cloud)[i].z, p.z(), 1e-5) << i;
  }
}

TEST(Reprojection, DepthLimitsAndStep) {
  cv::Mat disparity(4, 4, CV_16S, cv::Scalar(16 * 54));  // Z = 1.0044 m
  EXPECT_EQ(reproject(disparity, calibration(), 0.5, 15.0)->size(), 16u);
  EXPECT_EQ(reproject(disparity, calibration(), 1.1, 15.0)->size(), 0u);
  EXPECT_EQ(reproject(disparity, calibration(), 0.5, 1.0)->size(), 0u);
  EXPECT_EQ(reproject(disparity, calibration(), 0.5, 15.0, 2)->size(), 4u);
}

TEST(Reprojection, AMaskKeepsOnlyItsPixels) {
  cv::Mat disparity(4, 4, CV_16S, cv::Scalar(16 * 54));
  cv::Mat mask(4, 4, CV_8U, cv::Scalar(0));
  mask.at<std::uint8_t>(1, 2) = 255;
  mask.at<std::uint8_t>(3, 0) = 255;
  const auto cloud = reproject(disparity, calibration(), 0.5, 15.0, 1, mask);
  ASSERT_EQ(cloud->size(), 2u);
  const double z = 452.0 * 0.12 / 54.0;  // (u, v) = (2, 1) first, in row order
  EXPECT_NEAR((*cloud)[0].x, z * (2 - 320.0) / 452.0, 1e-5);
  EXPECT_NEAR((*cloud)[0].y, z * (1 - 240.0) / 452.0, 1e-5);
  EXPECT_NEAR((*cloud)[1].x, z * (0 - 320.0) / 452.0, 1e-5);
}

class MatcherOnShiftedTexture : public ::testing::TestWithParam<MatcherOptions::Algorithm> {};

TEST_P(MatcherOnShiftedTexture, RecoversTheShift) {
  MatcherOptions options;
  options.algorithm = GetParam();
  options.num_disparities = 64;
  if (options.algorithm == MatcherOptions::Algorithm::bm) options.block_size = 9;
  const auto matcher = make_matcher(options);
  const auto [left, right] = shifted_pair(24);
  const cv::Mat disparity = compute_disparity(*matcher, left, right);
  int valid = 0, right_value = 0;
  for (int v = 40; v < 440; ++v)
    for (int u = 100; u < 600; ++u) {
      const short d = disparity.at<short>(v, u);
      if (d <= 0) continue;
      ++valid;
      if (std::abs(d - 16 * 24) <= 4) ++right_value;  // within 1/4 px
    }
  EXPECT_GT(valid, 150000);
  EXPECT_GT(right_value, valid * 95 / 100);
  const auto cloud = reproject(disparity, calibration(), 0.5, 15.0);
  double z = 0;
  for (const auto& p : *cloud) z += p.z;
  EXPECT_NEAR(z / static_cast<double>(cloud->size()), 452.0 * 0.12 / 24, 0.02);
}

INSTANTIATE_TEST_SUITE_P(Algorithms, MatcherOnShiftedTexture,
                         ::testing::Values(MatcherOptions::Algorithm::sgbm, MatcherOptions::Algorithm::bm));

TEST(Downscale, HalvesTheCalibrationAndKeepsDepth) {
  const auto [left, right] = shifted_pair(24);
  const ScaledPair half = downscale(left, right, calibration(), 2);
  EXPECT_EQ(half.left.cols, 320);
  EXPECT_EQ(half.left.rows, 240);
  EXPECT_DOUBLE_EQ(half.calibration.fx, 226.0);
  EXPECT_DOUBLE_EQ(half.calibration.cx, 159.75);
  MatcherOptions options;
  options.num_disparities = 32;
  const auto matcher = make_matcher(options);
  const auto cloud = reproject(compute_disparity(*matcher, half.left, half.right), half.calibration, 0.5, 15.0);
  double z = 0;
  for (const auto& p : *cloud) z += p.z;
  // The same plane: f b / d is unchanged when f and d both halve.
  EXPECT_NEAR(z / static_cast<double>(cloud->size()), 452.0 * 0.12 / 24, 0.05);
  EXPECT_THROW(downscale(left, right, calibration(), 0), Error);
}

TEST(Matcher, RefusesOptionsOpenCvWouldReject) {
  MatcherOptions bad;
  bad.num_disparities = 100;
  EXPECT_THROW(make_matcher(bad), Error);
  bad = MatcherOptions{};
  bad.block_size = 4;
  EXPECT_THROW(make_matcher(bad), Error);
  bad = MatcherOptions{};
  bad.p1 = 500;
  bad.p2 = 100;
  EXPECT_THROW(make_matcher(bad), Error);
  const auto matcher = make_matcher(MatcherOptions{});
  EXPECT_THROW(compute_disparity(*matcher, cv::Mat(), cv::Mat()), Error);
  EXPECT_THROW(compute_disparity(*matcher, cv::Mat(10, 10, CV_8U), cv::Mat(12, 10, CV_8U)), Error);
  EXPECT_THROW(compute_disparity(*matcher, cv::Mat(10, 10, CV_32F), cv::Mat(10, 10, CV_32F)), Error);
}
