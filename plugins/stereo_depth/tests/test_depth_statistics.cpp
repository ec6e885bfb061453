// The report's depth statistics: points per frame, the share of pixels matched, and percentiles
// of depth to 1 %.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "depth_statistics.hpp"

using kestrel::stereo::DepthStatistics;

namespace {
pcl::PointCloud<pcl::PointXYZ> at_depths(const std::vector<float>& depths) {
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (float z : depths) cloud.push_back({0.1f, -0.2f, z});
  return cloud;
}
}  // namespace

TEST(DepthStatistics, PercentilesOfKnownDepthsToAPercent) {
  DepthStatistics s(0.5, 15.0);
  // 32,000 points evenly from 2 to 6 m over two frames of 64,000 sampled pixels each (every 16th
  // point is binned: 2,000 of them).
  std::vector<float> first, second;
  const int n = 32000;
  for (int i = 0; i < n / 2; ++i) first.push_back(2.0f + 4.0f * i / (n - 1));
  for (int i = n / 2; i < n; ++i) second.push_back(2.0f + 4.0f * i / (n - 1));
  s.add_frame(at_depths(first), 64000);
  s.add_frame(at_depths(second), 64000);
  EXPECT_EQ(s.frames(), 2u);
  EXPECT_DOUBLE_EQ(s.points_per_frame(), 16000.0);
  EXPECT_DOUBLE_EQ(s.valid_fraction(), 0.25);
  EXPECT_NEAR(*s.percentile(0.5), 4.0, 0.01 * 4.0);
  EXPECT_NEAR(*s.percentile(0.05), 2.2, 0.01 * 2.2);
  EXPECT_NEAR(*s.percentile(0.95), 5.8, 0.01 * 5.8);
}

TEST(DepthStatistics, NoDepthsNoPercentile) {
  DepthStatistics s(0.5, 15.0);
  EXPECT_FALSE(s.percentile(0.5));
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<float> none(16, nan);
  none[0] = -1.0f;
  s.add_frame(at_depths(none), 100);  // the one binned (the first) is behind the camera
  EXPECT_FALSE(s.percentile(0.5));
  EXPECT_DOUBLE_EQ(s.valid_fraction(), 0.16);
  // Beyond the range: in the end bins, not lost (16 of each, so that the binned ones are both).
  std::vector<float> outside(16, 0.1f);
  outside.resize(48, 40.0f);
  s.add_frame(at_depths(outside), 100);
  EXPECT_NEAR(*s.percentile(0.0), 0.5, 0.01);
  EXPECT_NEAR(*s.percentile(1.0), 15.0, 0.01 * 15.0);
}
