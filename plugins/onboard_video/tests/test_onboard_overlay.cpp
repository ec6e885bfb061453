// The onboard video's overlay on a known frame: where the aim point, a detection's box and the
// selected target land in the image, and in which colours.
#include <gmock/gmock.h>

#include <opencv2/imgcodecs.hpp>

#include "overlay.hpp"

using namespace kestrel;
using namespace kestrel::video;

namespace {

msg::StereoFrame grey_frame() {
  msg::StereoFrame f;
  f.left = cv::Mat(480, 640, CV_8UC1, cv::Scalar(128));
  f.right = f.left.clone();
  f.calibration.fx = f.calibration.fy = 304.0;
  return f;
}

cv::Vec3b at(const cv::Mat& image, cv::Point2d p) { return image.at<cv::Vec3b>(cvRound(p.y), cvRound(p.x)); }

// Lines are anti-aliased: a pixel on one is its colour to within a blend with the background.
bool near(const cv::Vec3b& pixel, const cv::Vec3b& colour) { return cv::norm(pixel, colour, cv::NORM_L2) < 45.0; }

}  // namespace

TEST(OnboardOverlay, ProjectsWithThePinholeModel) {
  msg::StereoCalibration c;
  c.fx = 300;
  c.fy = 310;
  c.cx = 320;
  c.cy = 240;
  const auto p = project({1.0, -0.5, 2.0}, c);
  ASSERT_TRUE(p);
  EXPECT_DOUBLE_EQ(p->x, 320 + 300 * 0.5);
  EXPECT_DOUBLE_EQ(p->y, 240 - 310 * 0.25);
  EXPECT_FALSE(project({0, 0, -1}, c));  // behind the camera
}

TEST(OnboardOverlay, DrawsTheAimPointABoxAndTheTarget) {
  const msg::StereoFrame frame = grey_frame();
  msg::Detections detections;
  msg::Detection d;
  d.position = {-1.0, 0.0, 5.0};
  d.extent = {0.5, 0.5, 0.0};
  detections.items.push_back(d);
  msg::Tracks tracks;
  msg::Track t;
  t.id = 7;
  t.state = Eigen::VectorXd::Zero(9);
  t.state.head<3>() = Eigen::Vector3d(1.0, -0.5, 4.0);
  tracks.items.push_back(t);
  tracks.selected_id = 7;
  const cv::Mat image = draw_overlay(frame, &detections, &tracks, {{0.0, 1.0, 2.0}, 0.5});
  ASSERT_EQ(image.type(), CV_8UC3);
  // Aim point [0, 1, 2]: (320, 240 + 304 / 2) = (320, 392), a green cross; its circle 76 px wide.
  EXPECT_TRUE(near(at(image, {320, 392}), {0, 255, 0})) << at(image, {320, 392});
  EXPECT_TRUE(near(at(image, {320 + 76, 392}), {0, 255, 0})) << at(image, {320 + 76, 392});
  // The box's left edge at u = 320 + 304 (-1.25 / 5) = 244, from v = 240 - 15.2 to 240 + 15.2
  // (orange, BGR).
  EXPECT_TRUE(near(at(image, {244, 240}), {0, 200, 255})) << at(image, {244, 240});
  // The target: a red ring of radius 10 around (320 + 76, 240 - 38).
  EXPECT_TRUE(near(at(image, {396 + 10, 202}), {0, 0, 255})) << at(image, {396 + 10, 202});
  // Elsewhere the image is untouched.
  EXPECT_EQ(at(image, {100, 100}), cv::Vec3b(128, 128, 128));
}
