#pragma once
// The paper's detector: Euclidean clusters of the filtered cloud (PCL), kept if their size lies
// in [min_points, max_points]; each cluster's centroid is a detection.
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <vector>

#include "kestrel/messages/detections.hpp"

namespace kestrel::clustering {

struct ClusterOptions {
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
