// The Euclidean clusterer on crafted clouds.
#include <gmock/gmock.h>

#include <kestrel/error.hpp>

#include "clustering.hpp"
#include "kestrel/testing/crafted_clouds.hpp"

using namespace kestrel;

using kestrel::testing::add_block;
using kestrel::testing::add_line;
using kestrel::testing::Cloud;

TEST(EuclideanClusterer, SizeLimitsAreInclusiveAtTwentyAndTwoHundred) {
  clustering::ClusterOptions options;  // 0.5 m, 20, 200
  for (const auto& [n, kept] : std::vector<std::pair<int, bool>>{{19, false}, {20, true}, {200, true}, {201, false}}) {
    auto cloud = std::make_shared<Cloud>();
    add_line(*cloud, 0.0f, 0.0f, 5.0f, n, 0.05f);
    const auto clusters = clustering::find_clusters(cloud, options);
    EXPECT_EQ(clusters.detections.size(), kept ? 1u : 0u) << n << " points";
    if (kept && !clusters.detections.empty()) {
      EXPECT_EQ(clusters.detections[0].point_count, n);
    }
  }
}

TEST(EuclideanClusterer, SeparationJustAboveAndBelowTheTolerance) {
  clustering::ClusterOptions options;
  for (const auto& [gap, clusters_expected] : std::vector<std::pair<float, std::size_t>>{{0.49f, 1}, {0.51f, 2}}) {
    auto cloud = std::make_shared<Cloud>();
    add_line(*cloud, 0.0f, 0.0f, 5.0f, 30, 0.01f);         // ends at x = 0.29
    add_line(*cloud, 0.29f + gap, 0.0f, 5.0f, 30, 0.01f);  // starts `gap` further on
    const auto clusters = clustering::find_clusters(cloud, options);
    EXPECT_EQ(clusters.detections.size(), clusters_expected) << "gap " << gap;
  }
}

TEST(EuclideanClusterer, CentroidExtentAndCount) {
  auto cloud = std::make_shared<Cloud>();
  add_block(*cloud, 1.0f, -0.5f, 4.0f, 3, 0.1f);  // 27 points, centroid (1.1, -0.4, 4.1), extent 0.2
  add_block(*cloud, -3.0f, 0.0f, 6.0f, 3, 0.1f);
  const auto clusters = clustering::find_clusters(cloud, {});
  ASSERT_EQ(clusters.detections.size(), 2u);
  const auto& d = clusters.detections[0].position.x() > 0 ? clusters.detections[0] : clusters.detections[1];
  EXPECT_EQ(d.point_count, 27);
  EXPECT_TRUE(d.position.isApprox(Eigen::Vector3d(1.1, -0.4, 4.1), 1e-5));
  EXPECT_TRUE(d.extent.isApprox(Eigen::Vector3d(0.2, 0.2, 0.2), 1e-5));
  EXPECT_TRUE(clustering::find_clusters(std::make_shared<Cloud>(), {}).detections.empty());
}

// Stereo at fx b = 36.48 px m (the paper's camera at 640x480) with half a pixel of noise: the
// tolerance along depth is 0.5 + z^2 * 0.5 / 36.48 m, 3.2 m at 14 m and 0.55 m at 2 m.
TEST(EuclideanClusterer, AFarObjectSpreadInDepthStaysOneClusterWithDepthNoise) {
  constexpr double kFocalBaseline = 36.48;
  auto far = std::make_shared<Cloud>();
  add_block(*far, 0.0f, 0.0f, 14.0f, 3, 0.1f);  // z 14.0 to 14.2
  add_block(*far, 0.0f, 0.0f, 14.8f, 3, 0.1f);  // 0.6 m further: apart for the paper's 0.5 m
  clustering::ClusterOptions paper;
  EXPECT_EQ(clustering::find_clusters(far, paper, kFocalBaseline).detections.size(), 2u);
  clustering::ClusterOptions noisy;
  noisy.depth_noise_px = 0.5;
  const auto joined = clustering::find_clusters(far, noisy, kFocalBaseline);
  ASSERT_EQ(joined.detections.size(), 1u);
  EXPECT_EQ(joined.detections[0].point_count, 54);
  EXPECT_NEAR(joined.detections[0].position.z(), 14.5, 1e-5);  // the points' own centroid, not stretched ones
  // Near the camera the tolerance is still about the paper's: 0.6 m apart at 2 m stay apart.
  auto near = std::make_shared<Cloud>();
  add_block(*near, 0.0f, 0.0f, 2.0f, 3, 0.1f);
  add_block(*near, 0.0f, 0.0f, 2.8f, 3, 0.1f);
  EXPECT_EQ(clustering::find_clusters(near, noisy, kFocalBaseline).detections.size(), 2u);
  // Sideways the tolerance does not grow: 0.6 m apart across at 14 m stay apart.
  auto side = std::make_shared<Cloud>();
  add_block(*side, 0.0f, 0.0f, 14.0f, 3, 0.1f);
  add_block(*side, 0.8f, 0.0f, 14.0f, 3, 0.1f);
  EXPECT_EQ(clustering::find_clusters(side, noisy, kFocalBaseline).detections.size(), 2u);
}

TEST(EuclideanClusterer, TheStretchedDepthHasTheToleranceAsItsSlope) {
  Cloud cloud;
  for (float z : {0.5f, 5.0f, 10.0f, 15.0f, 15.01f}) cloud.push_back({0.0f, 0.0f, z});
  const auto stretched = clustering::stretch_depth(cloud, 0.5, 0.5, 36.48);
  EXPECT_NEAR(stretched->points[0].z, 0.5, 2e-3);  // near: almost unchanged (c z^3 / 3 = 1 mm)
  // At 15 m a step dz becomes dz / (1 + c z^2), c = 0.5 / (36.48 * 0.5).
  const double slope = (stretched->points[4].z - stretched->points[3].z) / 0.01;
  EXPECT_NEAR(slope, 1.0 / (1.0 + 225.0 / 36.48), 2e-3);
  EXPECT_LT(stretched->points[2].z, stretched->points[3].z);  // order kept
}

TEST(EuclideanClusterer, DepthNoiseWithoutAStereoCloudIsRefused) {
  auto cloud = std::make_shared<Cloud>();
  add_block(*cloud, 0.0f, 0.0f, 5.0f, 3, 0.1f);
  clustering::ClusterOptions noisy;
  noisy.depth_noise_px = 0.5;
  EXPECT_THROW(clustering::find_clusters(cloud, noisy, 0.0), Error);
}
