#pragma once
// Point clouds whose voxels and clusters are known by construction, for the perception tests.
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

namespace kestrel::testing {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;

/// per_axis^3 points on a grid `spacing` apart from (x, y, z), so the count per voxel is known.
inline void add_block(Cloud& cloud, float x, float y, float z, int per_axis, float spacing) {
  for (int i = 0; i < per_axis; ++i)
    for (int j = 0; j < per_axis; ++j)
      for (int k = 0; k < per_axis; ++k) cloud.push_back({x + i * spacing, y + j * spacing, z + k * spacing});
}

/// A line of `n` points along x, `spacing` apart, starting at (x, y, z).
inline void add_line(Cloud& cloud, float x, float y, float z, int n, float spacing) {
  for (int i = 0; i < n; ++i) cloud.push_back({x + i * spacing, y, z});
}

}  // namespace kestrel::testing
