// The voxel filter and the Euclidean clusterer on crafted clouds.
#include <gmock/gmock.h>

#include "clustering.hpp"
#include "voxel_grid.hpp"

using namespace kestrel;

namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;

// `n` points inside the cube [x, x + side)^3 (a grid, so the count per voxel is known).
void add_block(Cloud& cloud, float x, float y, float z, int per_axis, float spacing) {
  for (int i = 0; i < per_axis; ++i)
    for (int j = 0; j < per_axis; ++j)
      for (int k = 0; k < per_axis; ++k) cloud.push_back({x + i * spacing, y + j * spacing, z + k * spacing});
}

// A line of `n` points along x, `spacing` apart, starting at (x, y, z).
void add_line(Cloud& cloud, float x, float y, float z, int n, float spacing) {
  for (int i = 0; i < n; ++i) cloud.push_back({x + i * spacing, y, z});
}

}  // namespace

TEST(VoxelFilter, OnePointPerOccupiedVoxelAndDepthCut) {
  Cloud cloud;
  // 4x4x4 points 0.025 m apart inside one 0.1 m voxel -> 1 point; a 10x10 grid of points 0.1 m
  // apart in a plane at z = 5.05 -> 100 voxels; 50 points beyond 10 m -> gone.
  add_block(cloud, 0.01f, 0.01f, 3.01f, 4, 0.025f);
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) cloud.push_back({0.05f + 0.1f * i, 0.05f + 0.1f * j, 5.05f});
  add_line(cloud, 0.0f, 0.0f, 12.0f, 50, 0.3f);
  voxel::VoxelOptions options;
  auto out = voxel::downsample(cloud, options);
  EXPECT_EQ(out->size(), 101u);
  for (const auto& p : *out) EXPECT_LE(p.z, 10.0f);
  // The single-voxel block collapses to its centroid.
  bool found = false;
  for (const auto& p : *out)
    if (std::abs(p.z - 3.0475f) < 1e-4) {
      found = true;
      EXPECT_NEAR(p.x, 0.0475, 1e-4);
    }
  EXPECT_TRUE(found);
  options.max_z_m = 4.0;
  EXPECT_EQ(voxel::downsample(cloud, options)->size(), 1u);
  options.max_z_m = 10.0;
  options.min_points_per_voxel = 2;
  EXPECT_EQ(voxel::downsample(cloud, options)->size(), 1u);  // only the dense voxel survives
}

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
