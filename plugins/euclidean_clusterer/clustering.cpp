#include "clustering.hpp"

#include <pcl/search/kdtree.h>
#include <pcl/segmentation/extract_clusters.h>

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

Clusters find_clusters(const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud, const ClusterOptions& o) {
  Clusters result;
  if (!cloud || cloud->empty()) return result;
  auto clusters = o.method == ClusterOptions::Method::pcl
                      ? pcl_clusters(cloud, o)
                      : grid_clusters(*cloud, o.tolerance_m, o.min_points, o.max_points);
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
