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
  // 1000 points evenly from 2 to 6 m over two frames of 2000 sampled pixels each.
  std::vector<float> first, second;
  for (int i = 0; i < 500; ++i) first.push_back(2.0f + 4.0f * i / 999.0f);
  for (int i = 500; i < 1000; ++i) second.push_back(2.0f + 4.0f * i / 999.0f);
  s.add_frame(at_depths(first), 2000);
  s.add_frame(at_depths(second), 2000);
  EXPECT_EQ(s.frames(), 2u);
  EXPECT_DOUBLE_EQ(s.points_per_frame(), 500.0);
  EXPECT_DOUBLE_EQ(s.valid_fraction(), 0.25);
  EXPECT_NEAR(*s.percentile(0.5), 4.0, 0.01 * 4.0);
  EXPECT_NEAR(*s.percentile(0.05), 2.2, 0.01 * 2.2);
  EXPECT_NEAR(*s.percentile(0.95), 5.8, 0.01 * 5.8);
}

TEST(DepthStatistics, NoPointsNoPercentileAndNonDepthsAreNotCounted) {
  DepthStatistics s(0.5, 15.0);
  EXPECT_FALSE(s.percentile(0.5));
  const float nan = std::numeric_limits<float>::quiet_NaN();
  s.add_frame(at_depths({nan, -1.0f, 0.0f}), 100);
  EXPECT_FALSE(s.percentile(0.5));
  EXPECT_DOUBLE_EQ(s.valid_fraction(), 0.0);
  // Beyond the range: in the end bins, not lost.
  s.add_frame(at_depths({0.1f, 40.0f, 40.0f}), 100);
  EXPECT_NEAR(*s.percentile(0.0), 0.5, 0.01);
  EXPECT_NEAR(*s.percentile(1.0), 15.0, 0.01 * 15.0);
}
