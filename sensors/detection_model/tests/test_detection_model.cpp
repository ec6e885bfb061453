// The detection-level camera model against answers known in closed form: what is in view, the
// recall table, and errors whose spread follows from the stereo geometry (depth error
// z^2 / (fx b) times the disparity error).
#include <gtest/gtest.h>

#include <cmath>
#include <kestrel/error.hpp>
#include <random>

#include "stereo_detection_model.hpp"

using kestrel::sensors::DetectionModelParams;
using kestrel::sensors::StereoDetectionModel;

namespace {

// fx = 300 px, baseline 0.12 m, 640 x 480, principal point at the centre; no noise, always seen.
DetectionModelParams exact() {
  DetectionModelParams p;
  p.camera.width = 640;
  p.camera.height = 480;
  p.camera.fx = p.camera.fy = 300.0;
  p.camera.cx = 319.5;
  p.camera.cy = 239.5;
  p.camera.baseline_m = 0.12;
  p.min_depth_m = 0.5;
  p.max_depth_m = 8.0;
  p.centroid_sigma_px = Eigen::Vector2d::Zero();
  p.disparity_sigma_px = 0.0;
  p.disparity_bias_px = 0.0;
  p.object_sigma_m = Eigen::Vector3d::Zero();
  p.recall_depth_m = {1.0};
  p.recall = {1.0};
  return p;
}

struct Spread {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero(), sd = Eigen::Vector3d::Zero();
  int seen = 0;
};

Spread spread(const StereoDetectionModel& model, const Eigen::Vector3d& p, int n, std::uint64_t seed = 7) {
  std::mt19937_64 rng(seed);
  Spread s;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero(), sum2 = Eigen::Vector3d::Zero();
  for (int i = 0; i < n; ++i)
    if (const auto d = model.observe(p, rng)) {
      ++s.seen;
      sum += *d;
      sum2 += d->cwiseProduct(*d);
    }
  s.mean = sum / s.seen;
  s.sd = (sum2 / s.seen - s.mean.cwiseProduct(s.mean)).cwiseSqrt();
  return s;
}

}  // namespace

TEST(DetectionModel, SeesWhatIsInTheImageAndTheDepthRange) {
  const StereoDetectionModel model(exact());
  EXPECT_TRUE(model.visible({0.0, 0.0, 5.0}));
  // At 4 m the image spans x in [-4.26, 4.27] m (u = 300 x / z + 319.5 in [0, 640)).
  EXPECT_TRUE(model.visible({4.2, 0.0, 4.0}));
  EXPECT_FALSE(model.visible({4.3, 0.0, 4.0}));
  EXPECT_FALSE(model.visible({0.0, -3.3, 4.0}));  // v < 0: above the image
  EXPECT_FALSE(model.visible({0.0, 0.0, 8.5}));   // beyond max_depth_m
  EXPECT_FALSE(model.visible({0.0, 0.0, 0.4}));   // nearer than min_depth_m
  EXPECT_FALSE(model.visible({0.0, 0.0, -2.0}));  // behind the camera
  std::mt19937_64 rng(1);
  EXPECT_FALSE(model.observe({0.0, 0.0, 9.0}, rng).has_value());
}

TEST(DetectionModel, WithoutNoiseADetectionIsWhereTheObjectIs) {
  const StereoDetectionModel model(exact());
  std::mt19937_64 rng(1);
  const Eigen::Vector3d p(0.7, -0.4, 6.0);
  const auto d = model.observe(p, rng);
  ASSERT_TRUE(d.has_value());
  EXPECT_LT((*d - p).norm(), 1e-12);
}

TEST(DetectionModel, TheRecallTableIsInterpolatedInDepthAndHeldAtItsEnds) {
  DetectionModelParams p = exact();
  p.recall_depth_m = {2.0, 4.0, 8.0};
  p.recall = {1.0, 0.8, 0.4};
  const StereoDetectionModel model(p);
  EXPECT_DOUBLE_EQ(model.detection_probability(1.0), 1.0);
  EXPECT_DOUBLE_EQ(model.detection_probability(3.0), 0.9);
  EXPECT_DOUBLE_EQ(model.detection_probability(6.0), 0.6);
  EXPECT_DOUBLE_EQ(model.detection_probability(9.0), 0.4);
  // 20000 draws at 6 m: 12000 expected, binomial sd 69; 5 sd either side.
  const Spread s = spread(model, {0.0, 0.0, 6.0}, 20000);
  EXPECT_NEAR(s.seen, 12000, 350);
}

TEST(DetectionModel, DepthErrorGrowsAsDepthSquaredOverFocalTimesBaseline) {
  DetectionModelParams p = exact();
  p.disparity_sigma_px = 0.2;
  const StereoDetectionModel model(p);
  for (const double z : {2.0, 4.0, 7.0}) {
    const Spread s = spread(model, {0.0, 0.0, z}, 40000);
    const double expected = z * z / (300.0 * 0.12) * 0.2;  // first order in the disparity error
    EXPECT_NEAR(s.sd.z(), expected, 0.03 * expected + 1e-4) << "z = " << z;
    EXPECT_LT(s.sd.x(), 1e-9);  // on the optical axis a disparity error moves nothing sideways
  }
}

TEST(DetectionModel, LateralErrorIsThePixelErrorScaledByDepthPlusTheObjectsOwn) {
  DetectionModelParams p = exact();
  p.centroid_sigma_px = {3.0, 1.5};
  p.object_sigma_m = {0.04, 0.0, 0.0};
  const StereoDetectionModel model(p);
  const double z = 5.0;
  const Spread s = spread(model, {0.0, 0.0, z}, 40000);
  const double x_expected = std::hypot(3.0 * z / 300.0, 0.04);  // 0.0640 m
  const double y_expected = 1.5 * z / 300.0;                    // 0.025 m
  EXPECT_NEAR(s.sd.x(), x_expected, 0.03 * x_expected);
  EXPECT_NEAR(s.sd.y(), y_expected, 0.03 * y_expected);
  EXPECT_NEAR(s.mean.x(), 0.0, 0.002);
}

TEST(DetectionModel, APositiveDisparityBiasBringsDetectionsNearer) {
  DetectionModelParams p = exact();
  p.disparity_bias_px = 0.5;
  const StereoDetectionModel model(p);
  std::mt19937_64 rng(1);
  const auto d = model.observe({0.0, 0.0, 6.0}, rng);
  ASSERT_TRUE(d.has_value());
  // d = 300 * 0.12 / 6 = 6 px; 6.5 px triangulates to 36 / 6.5 = 5.538 m.
  EXPECT_NEAR(d->z(), 36.0 / 6.5, 1e-12);
}

TEST(DetectionModel, TheSameSeedGivesTheSameDetections) {
  DetectionModelParams p = exact();
  p.disparity_sigma_px = 0.3;
  p.recall = {0.7};
  const StereoDetectionModel model(p);
  std::mt19937_64 a(42), b(42);
  for (int i = 0; i < 100; ++i) {
    const auto da = model.observe({0.5, 0.2, 5.0}, a), db = model.observe({0.5, 0.2, 5.0}, b);
    ASSERT_EQ(da.has_value(), db.has_value());
    if (da) {
      EXPECT_EQ(*da, *db);
    }
  }
}

TEST(DetectionModel, ParametersThatDescribeNoCameraOrProbabilityAreRefused) {
  DetectionModelParams p = exact();
  p.recall = {1.2};
  EXPECT_THROW(StereoDetectionModel{p}, kestrel::Error);
  p = exact();
  p.recall_depth_m = {2.0, 1.0};
  p.recall = {1.0, 1.0};
  EXPECT_THROW(StereoDetectionModel{p}, kestrel::Error);
  p = exact();
  p.recall = {};
  EXPECT_THROW(StereoDetectionModel{p}, kestrel::Error);
  p = exact();
  p.camera.baseline_m = 0.0;
  EXPECT_THROW(StereoDetectionModel{p}, kestrel::Error);
  p = exact();
  p.min_depth_m = 9.0;
  EXPECT_THROW(StereoDetectionModel{p}, kestrel::Error);
}
