#pragma once
// The paper's detector: Euclidean clusters of the filtered cloud, kept if their size lies in
// [min_points, max_points]; each cluster's centroid is a detection. The clusters are PCL's
// (EuclideanClusterExtraction), found either by PCL itself or by the hash grid of
// grid_clustering.hpp, which gives the same clusters faster.
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <vector>

#include "kestrel/messages/detections.hpp"

namespace kestrel::clustering {

struct ClusterOptions {
  enum class Method { grid, pcl };
  Method method = Method::grid;
  double tolerance_m = 0.5;
  int min_points = 20;
  int max_points = 200;
};

struct Clusters {
  std::vector<msg::Detection> detections;
  std::vector<std::vector<int>> indices;  ///< point indices of each kept cluster
};

Clusters find_clusters(const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud, const ClusterOptions& options);

}  // namespace kestrel::clustering
