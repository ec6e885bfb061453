// The simulated stereo camera's geometry: a rendered intruder appears where the pinhole model
// says, with the disparity its depth implies, and renders reproduce exactly.
#include <gmock/gmock.h>

#include <opencv2/imgproc.hpp>

#include "stereo_renderer.hpp"
#include "world_scene.hpp"

using namespace kestrel;
using namespace kestrel::sim;

namespace {

msg::StereoCalibration oCamS() {
  msg::StereoCalibration c;
  c.fx = c.fy = focal_from_hfov(640, 70.6);
  c.cx = 319.5;
  c.cy = 239.5;
  return c;
}

// Centroid of the pixels that differ between two renders (where the drone is).
cv::Point2d changed_centroid(const cv::Mat& with, const cv::Mat& without) {
  cv::Mat diff, grey;
  cv::absdiff(with, without, diff);
  cv::cvtColor(diff, grey, cv::COLOR_BGR2GRAY);
  const cv::Moments m = cv::moments(grey > 10, true);
  return {m.m10 / m.m00, m.m01 / m.m00};
}

}  // namespace

TEST(FocalFromFov, MatchesTheOCamS) {
  EXPECT_NEAR(focal_from_hfov(640, 70.6), 452.0, 1.0);
  EXPECT_NEAR(focal_from_hfov(640, 90.0), 320.0, 1e-9);
}

TEST(SimStereo, IntruderProjectsWhereThePinholeModelSaysWithItsDisparity) {
  SceneOptions options;
  options.clutter_count = 0;
  WorldScene world(options);
  StereoRenderer renderer(oCamS());
  const auto camera = geometry::level_camera({0, 0, 2}, 0.0);

  cv::Mat empty_left, empty_right, left, right;
  world.hide_unplaced_intruders();
  renderer.render(world.scene(), camera, empty_left, empty_right);
  // 0.4 m right and 0.2 m up of the optical axis, 5 m ahead. The model's centre of mass is its
  // origin, but its silhouette is not symmetric top to bottom (skids below), so compare x only
  // against the projection and y loosely.
  const Eigen::Vector3d in_camera(0.4, -0.2, 5.0);
  world.set_intruder(1, camera.to_world(in_camera), 0.0);
  renderer.render(world.scene(), camera, left, right);

  const auto c = oCamS();
  const cv::Point2d l = changed_centroid(left, empty_left);
  const cv::Point2d r = changed_centroid(right, empty_right);
  EXPECT_NEAR(l.x, c.cx + c.fx * in_camera.x() / in_camera.z(), 1.5);
  EXPECT_NEAR(l.y, c.cy + c.fy * in_camera.y() / in_camera.z(), 4.0);
  EXPECT_NEAR(l.x - r.x, c.fx * c.baseline_m / in_camera.z(), 0.75);  // disparity = f b / Z
  EXPECT_NEAR(l.y, r.y, 0.5);                                         // rectified: same row

  // Width of the silhouette: about 0.63 m across at 5 m.
  cv::Mat diff;
  cv::absdiff(left, empty_left, diff);
  cv::cvtColor(diff, diff, cv::COLOR_BGR2GRAY);
  const cv::Rect box = cv::boundingRect(diff > 10);
  EXPECT_NEAR(box.width, c.fx * 0.63 / 5.0, 8.0);

  // Rendering is deterministic.
  cv::Mat again_left, again_right;
  renderer.render(world.scene(), camera, again_left, again_right);
  EXPECT_EQ(cv::norm(left, again_left, cv::NORM_INF), 0.0);
}

TEST(SimStereo, ClutterStaysInItsRing) {
  SceneOptions options;
  options.clutter_count = 30;
  const WorldScene world(options);
  ASSERT_EQ(world.clutter_positions().size(), 30u);
  for (const auto& p : world.clutter_positions()) {
    EXPECT_GE(p.head<2>().norm(), options.clutter_min_range_m - 1e-9);
    EXPECT_LE(p.head<2>().norm(), options.clutter_max_range_m + 1e-9);
    EXPECT_LE(std::abs(std::atan2(p.y(), p.x())), options.clutter_bearing_deg * M_PI / 180.0 + 1e-9);
  }
}

TEST(SimStereo, BandClutterStandsWhollyBehindItsNearEdgeAndInView) {
  SceneOptions options;
  options.clutter_count = 40;
  options.clutter_layout = ClutterLayout::band;
  options.clutter_band_near_m = 6.0;
  options.clutter_band_far_m = 8.0;
  options.band_view.camera_position = {1.0, -2.0, 2.0};
  options.band_view.camera_yaw_rad = 0.5;
  options.band_view.half_fov_rad = 0.8;
  const WorldScene world(options);
  ASSERT_EQ(world.clutter_positions().size(), 40u);
  const Eigen::Vector2d axis(std::cos(0.5), std::sin(0.5)), side(-std::sin(0.5), std::cos(0.5));
  double widest = 0.0;
  for (std::size_t i = 0; i < world.clutter_positions().size(); ++i) {
    const Eigen::Vector2d rel = world.clutter_positions()[i].head<2>() - options.band_view.camera_position.head<2>();
    const double depth = rel.dot(axis), lateral = rel.dot(side);
    const double nearest = depth - world.clutter_footprint_radii()[i];  // no part of it nearer than the band
    EXPECT_GE(nearest, 6.0 - 1e-9);
    EXPECT_LE(nearest, 8.0 + 1e-9);
    EXPECT_LE(std::abs(lateral), depth * std::tan(0.8) + 1.0 + 1e-9);  // in view, a metre to spare
    widest = std::max(widest, std::abs(lateral));
  }
  EXPECT_GT(widest, 4.0);  // spread across the view, not bunched on the axis
}
