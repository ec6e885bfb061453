// The Euclidean clusterer on crafted clouds.
#include <gmock/gmock.h>

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
