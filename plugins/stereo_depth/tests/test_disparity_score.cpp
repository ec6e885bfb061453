// The Middlebury scores on maps whose answer is known, and stereo_depth's matcher on real pixels:
// the Middlebury 2006 Aloe pair (opencv-doc) against its ground truth.
#include <gmock/gmock.h>

#include <cmath>
#include <filesystem>
#include <kestrel/error.hpp>
#include <opencv2/imgcodecs.hpp>

#include "disparity_score.hpp"
#include "striped_matcher.hpp"

using namespace kestrel::stereo;

TEST(DisparityScore, CountsBadPixelsOnlyWhereTheTruthIsKnown) {
  cv::Mat truth(2, 5, CV_32F, cv::Scalar(10.0f)), estimate = truth.clone();
  truth.at<float>(0, 0) = NAN;  // unknown: never counted, whatever the estimate
  estimate.at<float>(0, 0) = 99.0f;
  estimate.at<float>(0, 1) = 11.5f;  // off by 1.5: bad-1, not bad-2
  estimate.at<float>(0, 2) = 7.0f;   // off by 3: both
  estimate.at<float>(0, 3) = NAN;    // unmatched
  estimate.at<float>(0, 4) = 10.25f;
  const DisparityScore s = score_disparity(estimate, truth);
  EXPECT_EQ(s.known, 9u);
  EXPECT_EQ(s.matched, 8u);
  EXPECT_DOUBLE_EQ(s.bad1, 2.0 / 8.0);
  EXPECT_DOUBLE_EQ(s.bad2, 1.0 / 8.0);
  EXPECT_DOUBLE_EQ(s.bad2_all, 2.0 / 9.0);  // the unmatched pixel and the one 3 px off
  EXPECT_DOUBLE_EQ(s.density(), 8.0 / 9.0);
  EXPECT_FLOAT_EQ(static_cast<float>(s.median_error_px), 0.0f);  // 5 of 8 exact
  EXPECT_THROW(score_disparity(estimate, cv::Mat(3, 5, CV_32F)), kestrel::Error);
}

TEST(DisparityScore, ConvertsSixteenthsAndReadsEightBitTruth) {
  cv::Mat d16 = (cv::Mat_<short>(1, 3) << 16 * 12 + 8, -16, 0);
  const cv::Mat px = disparity_in_pixels(d16);
  EXPECT_FLOAT_EQ(px.at<float>(0, 0), 12.5f);
  EXPECT_TRUE(std::isnan(px.at<float>(0, 1)));
  const std::string file = (std::filesystem::temp_directory_path() / "kestrel_truth_test.png").string();
  const cv::Mat eight_bit = (cv::Mat_<uchar>(1, 2) << 0, 42);
  cv::imwrite(file, eight_bit);
  const cv::Mat truth = read_disparity_truth(file);
  EXPECT_TRUE(std::isnan(truth.at<float>(0, 0)));  // 0: unknown in Middlebury 2006
  EXPECT_FLOAT_EQ(truth.at<float>(0, 1), 42.0f);
  EXPECT_THROW(read_disparity_truth("/nonexistent.pfm"), kestrel::Error);
}

// Real pixels: the Middlebury 2006 Aloe pair at full size (1282 x 1110, disparities to 211 px), as
// stereo_depth matches it (its defaults, two strips) with 256 disparities.
TEST(DisparityScore, StereoDepthMatchesTheAloePairToItsGroundTruth) {
  const std::string data = "/usr/share/doc/opencv-doc/examples/data/";
  const cv::Mat left = cv::imread(data + "aloeL.jpg", cv::IMREAD_GRAYSCALE);
  const cv::Mat right = cv::imread(data + "aloeR.jpg", cv::IMREAD_GRAYSCALE);
  ASSERT_FALSE(left.empty() || right.empty()) << "opencv-doc is not installed: run scripts/install-deps";
  const cv::Mat truth = read_disparity_truth(data + "aloeGT.png");
  MatcherOptions options;
  options.num_disparities = 256;
  StripedMatcher matcher(options, 2, 48);
  const DisparityScore s = score_disparity(disparity_in_pixels(matcher.compute(left, right)), truth);
  EXPECT_GT(s.known, 1000000u);
  // Measured: 69.6 % of the known pixels matched, 4.0 % of them off by more than 2 px, median
  // error 0.25 px (scripts/middlebury); the occluded band and the untextured background go unmatched.
  EXPECT_GT(s.density(), 0.6);
  EXPECT_LT(s.bad2, 0.06);
  EXPECT_LT(s.median_error_px, 0.5);
}
