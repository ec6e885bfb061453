// The voxel filter on a crafted cloud.
#include <gmock/gmock.h>

#include "kestrel/testing/crafted_clouds.hpp"
#include "voxel_grid.hpp"

using namespace kestrel;

using kestrel::testing::add_block;
using kestrel::testing::add_line;
using kestrel::testing::Cloud;

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
