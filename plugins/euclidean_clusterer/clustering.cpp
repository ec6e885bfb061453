#include "clustering.hpp"

#include <pcl/search/kdtree.h>
#include <pcl/segmentation/extract_clusters.h>

#include <cmath>
#include <kestrel/error.hpp>

#include "grid_clustering.hpp"

namespace kestrel::clustering {

namespace {

std::vector<std::vector<int>> pcl_clusters(const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud,
                                           const ClusterOptions& o) {
  // Unsorted radius searches: clustering only needs the neighbours, not their order.
  auto tree = std::make_shared<pcl::search::KdTree<pcl::PointXYZ>>(false);
  tree->setInputCloud(cloud);
  std::vector<pcl::PointIndices> clusters;
  pcl::EuclideanClusterExtraction<pcl::PointXYZ> extract;
  extract.setClusterTolerance(o.tolerance_m);
  extract.setMinClusterSize(o.min_points);
  extract.setMaxClusterSize(o.max_points);
  extract.setSearchMethod(tree);
  extract.setInputCloud(cloud);
  extract.extract(clusters);
  std::vector<std::vector<int>> out;
  out.reserve(clusters.size());
  for (auto& c : clusters) out.push_back(std::move(c.indices));
  return out;
}

}  // namespace

pcl::PointCloud<pcl::PointXYZ>::Ptr stretch_depth(const pcl::PointCloud<pcl::PointXYZ>& cloud, double tolerance_m,
                                                  double depth_noise_px, double focal_baseline_px_m) {
  if (!(focal_baseline_px_m > 0.0))
    throw Error(
        "depth_noise_px needs a stereo cloud (focal_baseline_px_m > 0): connect a stereo_depth cloud, through "
        "filters that keep it");
  const double root_c = std::sqrt(depth_noise_px / (focal_baseline_px_m * tolerance_m));
  auto out = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>(cloud);
  for (auto& p : out->points) p.z = static_cast<float>(std::atan(root_c * p.z) / root_c);
  return out;
}

Clusters find_clusters(const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud, const ClusterOptions& o,
                       double focal_baseline_px_m) {
  Clusters result;
  if (!cloud || cloud->empty()) return result;
  // Clusters are found on the stretched points; detections are made of the points themselves.
  const pcl::PointCloud<pcl::PointXYZ>::ConstPtr linked =
      o.depth_noise_px > 0.0 ? stretch_depth(*cloud, o.tolerance_m, o.depth_noise_px, focal_baseline_px_m) : cloud;
  auto clusters = o.method == ClusterOptions::Method::pcl
                      ? pcl_clusters(linked, o)
                      : grid_clusters(*linked, o.tolerance_m, o.min_points, o.max_points);
  for (auto& indices : clusters) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
    Eigen::Vector3d hi = -lo;
    for (int i : indices) {
      const auto& p = (*cloud)[static_cast<std::size_t>(i)];
      const Eigen::Vector3d v(p.x, p.y, p.z);
      sum += v;
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
    msg::Detection d;
    d.position = sum / static_cast<double>(indices.size());
    d.extent = hi - lo;
    d.point_count = static_cast<int>(indices.size());
    result.detections.push_back(d);
    result.indices.push_back(std::move(indices));
  }
  return result;
}

}  // namespace kestrel::clustering
