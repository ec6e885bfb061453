#include "voxel_grid.hpp"

#include <pcl/filters/passthrough.h>
#include <pcl/filters/voxel_grid.h>

namespace kestrel::voxel {

pcl::PointCloud<pcl::PointXYZ>::Ptr downsample(const pcl::PointCloud<pcl::PointXYZ>& cloud, const VoxelOptions& o) {
  auto input = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>(cloud);
  auto near = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  pcl::PassThrough<pcl::PointXYZ> pass;
  pass.setInputCloud(input);
  pass.setFilterFieldName("z");
  pass.setFilterLimits(static_cast<float>(o.min_z_m), static_cast<float>(o.max_z_m));
  pass.filter(*near);

  auto out = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  pcl::VoxelGrid<pcl::PointXYZ> grid;
  grid.setInputCloud(near);
  const auto leaf = static_cast<float>(o.leaf_size_m);
  grid.setLeafSize(leaf, leaf, leaf);
  grid.setMinimumPointsNumberPerVoxel(static_cast<unsigned>(o.min_points_per_voxel));
  grid.filter(*out);
  return out;
}

}  // namespace kestrel::voxel
