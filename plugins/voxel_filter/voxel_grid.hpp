#pragma once
// The paper's point-cloud reduction: discard points beyond a depth along the camera's z axis
// (pass-through), then keep one point per occupied voxel (PCL VoxelGrid, centroid of its points).
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

namespace kestrel::voxel {

struct VoxelOptions {
  double leaf_size_m = 0.1;
  double min_z_m = 0.0;
  double max_z_m = 10.0;
  int min_points_per_voxel = 1;
};

pcl::PointCloud<pcl::PointXYZ>::Ptr downsample(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                                               const VoxelOptions& options);

}  // namespace kestrel::voxel
