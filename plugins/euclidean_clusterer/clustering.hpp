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
  /// Stereo's disparity noise between neighbours, px. Far away a disparity error moves a point a
  /// long way along its ray (z^2 e / (fx b)), so one object's points spread in depth wider than
  /// the tolerance and split. With e > 0 the tolerance along the depth axis widens to
  /// tolerance_m + z^2 e / (fx b) at depth z; 0: the same tolerance everywhere (the paper).
  double depth_noise_px = 0.0;
};

struct Clusters {
  std::vector<msg::Detection> detections;
  std::vector<std::vector<int>> indices;  ///< point indices of each kept cluster
};

/// `focal_baseline_px_m` is the cloud's fx times baseline (msg::PointCloud), needed when
/// options.depth_noise_px > 0 (kestrel::Error otherwise).
Clusters find_clusters(const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud, const ClusterOptions& options,
                       double focal_baseline_px_m = 0.0);

/// The depth axis stretched so that a depth-dependent tolerance becomes a constant one: with
/// c = depth_noise_px / (focal_baseline * tolerance), the tolerance at depth z is
/// tolerance * (1 + c z^2), and z maps to atan(sqrt(c) z) / sqrt(c), whose slope is
/// 1 / (1 + c z^2). Near the camera (c z^2 << 1) it is z itself.
pcl::PointCloud<pcl::PointXYZ>::Ptr stretch_depth(const pcl::PointCloud<pcl::PointXYZ>& cloud, double tolerance_m,
                                                  double depth_noise_px, double focal_baseline_px_m);

}  // namespace kestrel::clustering
