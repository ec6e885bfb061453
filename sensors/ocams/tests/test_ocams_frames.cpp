// The oCamS frame core on frames whose answer is known: two GRBG mosaics packed as the camera
// sends them come back unpacked exactly, clock included; the pixels the clock overwrote take
// their Bayer neighbours' values; demosaicing a mosaic of a colour image gives that image back
// in flat regions; and the pipeline rectifies with the calibration it was given.
#include <gmock/gmock.h>

#include <kestrel/error.hpp>
#include <opencv2/imgproc.hpp>

#include "frame_pipeline.hpp"
#include "raw_frame.hpp"

using namespace kestrel;
using namespace kestrel::ocams;

namespace {

cv::Mat noise(int width, int height, int seed) {
  cv::Mat m(height, width, CV_8UC1);
  cv::theRNG().state = static_cast<std::uint64_t>(seed);
  cv::randu(m, 0, 256);
  return m;
}

calibration::CameraInfo rectified_info(double tx) {
  calibration::CameraInfo c;
  c.width = 640;
  c.height = 480;
  c.k = {400, 0, 319.5, 0, 400, 239.5, 0, 0, 1};
  c.d.assign(5, 0.0);
  c.r = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  c.p = {400, 0, 319.5, tx, 0, 400, 239.5, 0, 0, 0, 1, 0};
  return c;
}

}  // namespace

TEST(OcamsRawFrame, PackedMosaicsComeBackExactlyWithTheClock) {
  const cv::Mat left = noise(640, 480, 1), right = noise(640, 480, 2);
  const auto raw = pack(left, right, 0xA1B2C3D4u);
  ASSERT_EQ(raw.size(), 640u * 480u * 2u);
  EXPECT_EQ(raw[0], 0xD4);                          // little-endian, over the first words
  EXPECT_EQ(raw[5], left.at<std::uint8_t>(0, 2));   // high byte: left
  EXPECT_EQ(raw[4], right.at<std::uint8_t>(0, 2));  // low byte: right
  const BayerPair pair = unpack(raw, 640, 480);
  EXPECT_EQ(pair.device_ms, 0xA1B2C3D4u);
  // Every pixel but the two the clock overwrote, which take the same-colour pixel two rows down.
  cv::Mat expected_left = left.clone(), expected_right = right.clone();
  for (int c = 0; c < 2; ++c) {
    expected_left.at<std::uint8_t>(0, c) = left.at<std::uint8_t>(2, c);
    expected_right.at<std::uint8_t>(0, c) = right.at<std::uint8_t>(2, c);
  }
  EXPECT_EQ(cv::countNonZero(pair.left != expected_left), 0);
  EXPECT_EQ(cv::countNonZero(pair.right != expected_right), 0);
}

TEST(OcamsRawFrame, AShortOrOddFrameIsRefusedWithItsSize) {
  const auto raw = pack(noise(64, 48, 1), noise(64, 48, 2), 7);
  try {
    unpack(std::span(raw).first(raw.size() - 1), 64, 48);
    FAIL() << "a short frame was accepted";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("6143 bytes for 64x48 (6144 expected)"));
  }
  EXPECT_THROW(unpack(raw, 63, 48), Error);
  EXPECT_THROW(unpack({}, 0, 0), Error);
}

TEST(OcamsRawFrame, DemosaicingAColourImagesMosaicGivesItBack) {
  // Flat colour patches: away from their edges, interpolation has nothing to get wrong.
  cv::Mat image(96, 128, CV_8UC3, cv::Scalar(30, 120, 200));
  image(cv::Rect(64, 0, 64, 96)).setTo(cv::Scalar(220, 60, 10));
  const cv::Mat back = demosaic_grbg(mosaic_grbg(image), true);
  cv::Mat diff;
  cv::absdiff(back(cv::Rect(4, 4, 56, 88)), image(cv::Rect(4, 4, 56, 88)), diff);
  EXPECT_EQ(cv::countNonZero(diff.reshape(1) > 1), 0);
  cv::absdiff(back(cv::Rect(68, 4, 56, 88)), image(cv::Rect(68, 4, 56, 88)), diff);
  EXPECT_EQ(cv::countNonZero(diff.reshape(1) > 1), 0);
  // Taken as another pattern, the colours swap: the test can tell.
  cv::Mat wrong;
  cv::cvtColor(mosaic_grbg(image), wrong, cv::COLOR_BayerRG2BGR);
  EXPECT_GT(std::abs(wrong.at<cv::Vec3b>(40, 30)[0] - 30), 50);
  const cv::Mat grey = demosaic_grbg(mosaic_grbg(image), false);
  cv::Mat expected;
  cv::cvtColor(image, expected, cv::COLOR_BGR2GRAY);
  EXPECT_NEAR(grey.at<std::uint8_t>(40, 30), expected.at<std::uint8_t>(40, 30), 2);
}

TEST(OcamsFramePipeline, ARawFrameBecomesTheRectifiedStereoFrame) {
  auto rectifier = std::make_shared<calibration::StereoRectifier>(rectified_info(0.0), rectified_info(-400 * 0.12));
  const FramePipeline pipeline({640, 480, false}, rectifier);
  cv::Mat left(480, 640, CV_8UC3, cv::Scalar(50, 100, 150)), right(480, 640, CV_8UC3, cv::Scalar(150, 100, 50));
  const auto raw = pack(mosaic_grbg(left), mosaic_grbg(right), 1234);
  std::uint32_t device_ms = 0;
  const msg::StereoFrame f = pipeline.process(raw, Time(5), 9, &device_ms);
  EXPECT_EQ(device_ms, 1234u);
  EXPECT_EQ(f.stamp, Time(5));
  EXPECT_EQ(f.frame_index, 9u);
  ASSERT_EQ(f.left.type(), CV_8UC1);
  EXPECT_EQ(f.calibration.fx, 400.0);
  EXPECT_NEAR(f.calibration.baseline_m, 0.12, 1e-15);
  cv::Mat grey_left;
  cv::cvtColor(left, grey_left, cv::COLOR_BGR2GRAY);
  EXPECT_NEAR(f.left.at<std::uint8_t>(240, 320), grey_left.at<std::uint8_t>(240, 320), 2);
  EXPECT_THROW(pipeline.process(std::span(raw).first(100), Time(0), 0), Error);
  EXPECT_THROW(FramePipeline({1280, 960, false}, rectifier), Error);  // calibrated at another size
}
