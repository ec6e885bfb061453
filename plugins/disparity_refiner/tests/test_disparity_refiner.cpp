// The object's disparity measured as a whole, on stereo pairs whose answer is known: a textured
// patch shifted by a sub-pixel disparity, and a textured plane at a known depth.
#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <random>

#include "object_disparity.hpp"

using namespace kestrel;
using namespace kestrel::refine;

namespace {

msg::StereoCalibration calibration() {
  msg::StereoCalibration c;
  c.width = 640;
  c.height = 480;
  c.fx = c.fy = 304.0;
  c.cx = 319.5;
  c.cy = 239.5;
  c.baseline_m = 0.12;
  return c;
}

// A smooth random texture (noise blurred by sigma), CV_32F.
cv::Mat texture(int width, int height, double sigma, std::uint64_t seed) {
  cv::Mat noise(height, width, CV_32F);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<float> grey(0.0f, 255.0f);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) noise.at<float>(y, x) = grey(rng);
  cv::GaussianBlur(noise, noise, {0, 0}, sigma);
  return noise;
}

// The right image of a scene whose every pixel has disparity d: R(u) = L(u + d), interpolated
// from a texture sampled at 8x so that the shift is exact to well below 0.01 px.
std::pair<cv::Mat, cv::Mat> shifted_pair(double d, std::uint64_t seed) {
  const cv::Mat fine = texture(640 * 8 + 800, 480, 8.0 * 1.2, seed);  // features of about a pixel
  cv::Mat left(480, 640, CV_32F), right(480, 640, CV_32F);
  for (int y = 0; y < 480; ++y)
    for (int x = 0; x < 640; ++x) {
      const auto at = [&](double u) {
        const double f = u * 8.0 + 400.0;
        const int i = static_cast<int>(std::floor(f));
        const double w = f - i;
        return static_cast<float>((1 - w) * fine.at<float>(y, i) + w * fine.at<float>(y, i + 1));
      };
      left.at<float>(y, x) = at(x);
      right.at<float>(y, x) = at(x + d);
    }
  return {left, right};
}

// The points stereo_depth would give for the pixels of a rectangle with disparity `sgbm`.
pcl::PointCloud<pcl::PointXYZ> points(const msg::StereoCalibration& c, cv::Rect r, double sgbm) {
  pcl::PointCloud<pcl::PointXYZ> cloud;
  const double z = c.fx * c.baseline_m / sgbm;
  for (int v = r.y; v < r.y + r.height; ++v)
    for (int u = r.x; u < r.x + r.width; ++u)
      cloud.push_back(pcl::PointXYZ(static_cast<float>((u - c.cx) * z / c.fx),
                                    static_cast<float>((v - c.cy) * z / c.fy), static_cast<float>(z)));
  return cloud;
}

}  // namespace

TEST(ObjectDisparity, TheMaskIsTheBoxsPixelsLessTheirSilhouette) {
  const auto c = calibration();
  const cv::Rect r(300, 200, 30, 20);
  const auto cloud = points(c, r, 6.0);
  const Eigen::Vector3d centre(0.0, -0.8, 6.08), half(10.0, 10.0, 1.0);  // a box around all of them
  const auto mask = object_mask(cloud, c, centre, half, 0.0, 1, 20);
  ASSERT_TRUE(mask.has_value());
  EXPECT_EQ(mask->roi, r);
  EXPECT_EQ(mask->count, 28 * 18);  // one pixel peeled off each side
  EXPECT_NEAR(mask->sgbm_disparity, 6.0, 1e-4);
  // Too few pixels left: none.
  EXPECT_FALSE(object_mask(cloud, c, centre, half, 0.0, 1, 1000).has_value());
  // A box that holds none of the points: none.
  EXPECT_FALSE(object_mask(cloud, c, {5.0, 5.0, 20.0}, {0.1, 0.1, 0.1}, 0.0, 1, 1).has_value());
}

// SGBM said 7 px; the patch is really at 7.3 px: the whole-object match finds it within 0.05 px.
TEST(ObjectDisparity, ASubPixelShiftIsRecoveredWithinFiveHundredthsOfAPixel) {
  const auto c = calibration();
  for (const double truth : {7.3, 4.75, 12.1}) {
    const auto [left, right] = shifted_pair(truth, 11);
    const cv::Rect r(300, 220, 25, 18);  // a drone about 25 px wide: 7.5 m away
    const auto mask = object_mask(points(c, r, std::round(truth)), c, {0, 0, 0}, {100, 100, 100}, 0.0, 1, 20);
    ASSERT_TRUE(mask.has_value());
    const auto d = match_disparity(left, right, *mask, {});
    ASSERT_TRUE(d.has_value()) << truth;
    EXPECT_NEAR(*d, truth, 0.05) << truth;
  }
}

// A textured plane 5 m ahead (disparity 7.296 px), seen through a 40 x 30 px window at the image
// centre, SGBM off by 0.4 px: refined and placed, the detection is on the plane, under the
// window's centre.
TEST(ObjectDisparity, ATexturedPlaneAtAKnownDepthIsPlacedRight) {
  const auto c = calibration();
  const double depth = 5.0, truth = c.fx * c.baseline_m / depth;
  const auto [left, right] = shifted_pair(truth, 5);
  const cv::Rect r(300, 225, 40, 30);
  const auto mask = object_mask(points(c, r, truth + 0.4), c, {0, 0, 0}, {100, 100, 100}, 0.0, 1, 20);
  ASSERT_TRUE(mask.has_value());
  const auto d = match_disparity(left, right, *mask, {});
  ASSERT_TRUE(d.has_value());
  const Eigen::Vector3d p = place(c, *mask, *d);
  // 0.05 px of disparity is 0.034 m of depth at 5 m.
  EXPECT_NEAR(p.z(), depth, 0.034);
  const double u = r.x + (r.width - 1) / 2.0, v = r.y + (r.height - 1) / 2.0;
  EXPECT_NEAR(p.x(), (u - c.cx) * depth / c.fx, 1e-3);
  EXPECT_NEAR(p.y(), (v - c.cy) * depth / c.fy, 1e-3);
  // Without refinement the same pixels would place it 0.25 m too near.
  EXPECT_LT(place(c, *mask, mask->sgbm_disparity).z(), depth - 0.2);
}

TEST(ObjectDisparity, TheRobustMeanIgnoresPixelsThatBledOntoTheBackground) {
  const auto c = calibration();
  const cv::Rect r(300, 200, 20, 20);
  auto cloud = points(c, r, 8.0);
  // A tenth of the pixels carry the background's disparity (1 px): far behind.
  for (std::size_t i = 0; i < cloud.size(); i += 10) cloud[i].getVector3fMap() *= 8.0f;
  const auto mask = object_mask(cloud, c, {0, -0.4, 4.5}, {10, 10, 10}, 0.0, 0, 20);
  ASSERT_TRUE(mask.has_value());
  const auto d = robust_mean_disparity(*mask);
  ASSERT_TRUE(d.has_value());
  EXPECT_NEAR(*d, 8.0, 1e-4);
}

TEST(ObjectDisparity, NoTextureNoMatch) {
  const auto c = calibration();
  const cv::Mat flat(480, 640, CV_32F, cv::Scalar(128.0f));
  const auto mask = object_mask(points(c, {300, 200, 20, 20}, 6.0), c, {0, 0, 0}, {100, 100, 100}, 0.0, 1, 20);
  ASSERT_TRUE(mask.has_value());
  EXPECT_FALSE(match_disparity(flat, flat, *mask, {}).has_value());
}

TEST(ObjectDisparity, CoarsePointsStandForSquaresOfPixels) {
  // Matched at half resolution: one point per 2x2 block, at the block's centre.
  const auto c = calibration();
  const cv::Rect r(300, 200, 24, 16);
  const double z = 5.0;
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (int v = r.y; v < r.y + r.height; v += 2)
    for (int u = r.x; u < r.x + r.width; u += 2) {
      const double uc = u + 0.5, vc = v + 0.5;  // the block's centre in full-resolution pixels
      cloud.push_back(pcl::PointXYZ(static_cast<float>((uc - c.cx) * z / c.fx),
                                    static_cast<float>((vc - c.cy) * z / c.fy), static_cast<float>(z)));
    }
  const auto mask = object_mask(cloud, c, {0, 0, 0}, {100, 100, 100}, 0.0, 0, 20, 2);
  ASSERT_TRUE(mask.has_value());
  EXPECT_EQ(mask->roi, r);
  EXPECT_EQ(mask->count, r.area());
  const Eigen::Vector3d p = place(c, *mask, c.fx * c.baseline_m / z);
  EXPECT_NEAR(p.x(), (r.x + (r.width - 1) / 2.0 - c.cx) * z / c.fx, 1e-9);  // centred, not half a pixel off
  EXPECT_NEAR(p.y(), (r.y + (r.height - 1) / 2.0 - c.cy) * z / c.fy, 1e-9);
}

namespace {

// A textured object (disparity 8) in front of a background (disparity 1), textured or plain;
// integer disparities, so the right image is the left one's pixels moved.
std::pair<cv::Mat, cv::Mat> object_before_background(cv::Rect object, bool textured_background) {
  const cv::Mat object_texture = texture(640, 480, 1.2, 3);
  const cv::Mat background = textured_background ? texture(640, 480, 1.2, 4) : cv::Mat(480, 640, CV_32F, 200.0f);
  cv::Mat left(480, 640, CV_32F), right(480, 640, CV_32F);
  for (int y = 0; y < 480; ++y)
    for (int x = 0; x < 640; ++x) {
      left.at<float>(y, x) = object.contains({x, y}) ? object_texture.at<float>(y, x) : background.at<float>(y, x);
      const cv::Point seen(x + 8, y);  // where the object pixel seen here sits in the left image
      right.at<float>(y, x) =
          object.contains(seen) ? object_texture.at<float>(seen) : background.at<float>(y, std::min(x + 1, 639));
    }
  return {left, right};
}

}  // namespace

TEST(ObjectDisparity, BackgroundTheObjectBledOntoIsTakenOutAndPlainSkyStays) {
  const auto c = calibration();
  const cv::Rect object(300, 200, 30, 20);
  const cv::Rect bled(object.x - 4, object.y - 4, object.width + 8, object.height + 8);  // a block matcher's spread
  for (const bool textured : {true, false}) {
    const auto [left, right] = object_before_background(object, textured);
    auto mask = object_mask(points(c, bled, 8.0), c, {0, 0, 0}, {100, 100, 100}, 0.0, 0, 20);
    ASSERT_TRUE(mask.has_value());
    const int ring = bled.area() - object.area();
    const int removed = drop_background(left, right, *mask, {});
    int object_kept = 0;
    for (int y = object.y; y < object.y + object.height; ++y)
      for (int x = object.x; x < object.x + object.width; ++x)
        object_kept += mask->pixels.at<std::uint8_t>(y - mask->roi.y, x - mask->roi.x) != 0;
    EXPECT_GE(object_kept, object.area() * 95 / 100) << (textured ? "textured" : "plain");
    EXPECT_EQ(mask->count, bled.area() - removed);
    if (textured)
      EXPECT_GE(removed, ring * 70 / 100);  // the ring's window straddles the object within 2 px of it
    else
      EXPECT_LE(removed, ring * 10 / 100);  // every disparity explains a plain sky alike
  }
}

TEST(ObjectDisparity, TheCentreLiesBehindTheSurfaceAlongTheLineOfSight) {
  const Eigen::Vector3d centre = centre_behind({3.0, 0.0, 4.0}, 0.5);
  EXPECT_TRUE(centre.isApprox(Eigen::Vector3d(3.3, 0.0, 4.4), 1e-12));
  EXPECT_TRUE(centre_behind({1.0, 2.0, 3.0}, 0.0).isApprox(Eigen::Vector3d(1.0, 2.0, 3.0)));
}
