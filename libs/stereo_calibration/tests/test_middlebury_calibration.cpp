// Middlebury's calib.txt: the Motorcycle and Aloe files kestrel ships read into camera_info
// pairs, the right image moved by doffs so that disparity gives depth, and malformed files refused
// with the line at fault.
#include <gmock/gmock.h>

#include <kestrel/error.hpp>
#include <opencv2/imgproc.hpp>

#include "kestrel/stereo_calibration/middlebury_calibration.hpp"
#include "kestrel/stereo_calibration/stereo_rectifier.hpp"

using namespace kestrel::calibration;
using ::testing::HasSubstr;

namespace {
const std::string kExamples = std::string(KESTREL_SOURCE_DIR) + "/examples/middlebury/";

std::string error_of(const std::string& text) {
  try {
    parse_middlebury_calibration(text, "calib.txt");
  } catch (const kestrel::Error& e) {
    return e.what();
  }
  return "no error";
}

const std::string kGood =
    "cam0=[100 0 50; 0 100 40; 0 0 1]\ncam1=[100 0 60; 0 100 40; 0 0 1]\ndoffs=10\nbaseline=200\nwidth=120\n"
    "height=80\nndisp=32\nisint=0\n";
}  // namespace

TEST(MiddleburyCalibration, ReadsTheMotorcyclePair) {
  const MiddleburyCalibration c = load_middlebury_calibration(kExamples + "motorcycle_calib.txt");
  EXPECT_DOUBLE_EQ(c.cam0[0], 994.978);
  EXPECT_DOUBLE_EQ(c.cam1[2], 342.279);
  EXPECT_DOUBLE_EQ(c.doffs, 31.086);
  EXPECT_DOUBLE_EQ(c.baseline_mm, 193.001);
  EXPECT_EQ(c.width, 741);
  EXPECT_EQ(c.height, 500);
  EXPECT_EQ(c.ndisp, 68);
  const auto [left, right] = c.camera_infos();
  const StereoRectifier rectifier(left, right);
  EXPECT_NEAR(rectifier.calibration().baseline_m, 0.193001, 1e-9);
  EXPECT_DOUBLE_EQ(rectifier.calibration().cx, 311.193);
  EXPECT_FALSE(rectifier.passthrough());  // the right image is moved by doffs
  EXPECT_TRUE(StereoRectifier(load_middlebury_calibration(kExamples + "aloe_calib.txt").camera_infos().first,
                              load_middlebury_calibration(kExamples + "aloe_calib.txt").camera_infos().second)
                  .passthrough());  // doffs 0: nothing to move
}

TEST(MiddleburyCalibration, TheRightImageMovesByDoffsSoThatDisparityGivesDepth) {
  const MiddleburyCalibration c = parse_middlebury_calibration(kGood, "calib.txt");
  const auto [left, right] = c.camera_infos();
  StereoRectifier rectifier(left, right);
  // A bright column at x = 70 in the right image lands at x = 60 after rectification: a disparity
  // d in the pair becomes d + doffs, and baseline * f / (d + doffs) is the depth.
  cv::Mat image(80, 120, CV_8U, cv::Scalar(0)), blank = image.clone();
  image.col(70).setTo(255);
  cv::Mat out_left, out_right;
  rectifier.rectify(blank, image, out_left, out_right);
  cv::Point peak;
  cv::minMaxLoc(out_right.row(40), nullptr, nullptr, nullptr, &peak);
  EXPECT_EQ(peak.x, 60);
}

TEST(MiddleburyCalibration, MalformedFilesAreRefusedWithTheLine) {
  EXPECT_THAT(error_of("cam0=[100 0 50; 0 100 40; 0 0 1]\n"), HasSubstr("no 'cam1'"));
  EXPECT_THAT(error_of("cam0=[100 0 50; 0 100 40]\n"), HasSubstr("calib.txt:1: cam0: 6 numbers"));
  EXPECT_THAT(error_of("just words\n"), HasSubstr("calib.txt:1: expected key=value"));
  std::string bad = kGood;
  bad.replace(bad.find("doffs=10"), 8, "doffs=12");
  EXPECT_THAT(error_of(bad), HasSubstr("calib.txt:3: doffs = 12 is not cam1's cx - cam0's cx (10)"));
  bad = kGood;
  bad.replace(bad.find("width=120"), 9, "width=1.5");
  EXPECT_THAT(error_of(bad), HasSubstr("calib.txt:5: width = 1.5 is not a whole number"));
  bad = kGood;
  bad.replace(bad.find("baseline=200"), 12, "baseline=abc");
  EXPECT_THAT(error_of(bad), HasSubstr("calib.txt:4: baseline: 'abc' is not a number"));
  EXPECT_THAT(error_of(kGood + "width=3\n"), HasSubstr("calib.txt:9: 'width' given twice (first on line 5)"));
  EXPECT_THROW(load_middlebury_calibration("/nonexistent/calib.txt"), kestrel::Error);
}
