#pragma once
// Euclidean clustering on a hash grid: the same clusters as PCL's EuclideanClusterExtraction
// (points closer than the tolerance are linked; a cluster is a connected set), found in a
// fraction of the time on the few thousand voxels a filtered frame holds.
//
// Points are binned into cubic cells of side tolerance / sqrt(3) (shrunk a hair), so that every
// two points of one cell are neighbours: a cell is joined whole. Two cells can hold neighbours
// only if they are at most two cells apart on every axis; such a pair is joined when one pair of
// their points is closer than the tolerance, and skipped when they are already one cluster.
// Closeness is decided exactly as PCL's kd-tree radius search decides it: the squared distance
// summed in float, strictly below the squared tolerance rounded to float.
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <vector>

namespace kestrel::clustering {

/// Connected sets of points closer than `tolerance` whose size lies in [min_points, max_points],
/// each as its points' indices in increasing order, larger sets first (equal sizes: the one with
/// the smallest index first).
std::vector<std::vector<int>> grid_clusters(const pcl::PointCloud<pcl::PointXYZ>& cloud, double tolerance,
                                            int min_points, int max_points);

}  // namespace kestrel::clustering
