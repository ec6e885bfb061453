#pragma once
// What the matcher made of its frames, for the report: points per frame, the share of the sampled
// pixels that became points, and percentiles of their depth. The depths go into a histogram in
// steps of 1 % of depth (finer than a pixel of disparity wherever the disparity is under 100 px),
// so the memory stays the same however long the run.
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstdint>
#include <optional>
#include <vector>

namespace kestrel::stereo {

class DepthStatistics {
 public:
  /// Depths outside [min_depth_m, max_depth_m] are counted in the end bins.
  DepthStatistics(double min_depth_m, double max_depth_m);
  /// One frame's points (camera frame: depth is z), out of `pixels` sampled pixels.
  void add_frame(const pcl::PointCloud<pcl::PointXYZ>& points, std::uint64_t pixels);

  std::uint64_t frames() const { return frames_; }
  double points_per_frame() const { return frames_ ? static_cast<double>(points_) / frames_ : 0.0; }
  /// Points over pixels sampled, over all frames.
  double valid_fraction() const { return pixels_ ? static_cast<double>(points_) / pixels_ : 0.0; }
  /// The depth below which `fraction` (0 to 1) of the points lie, to 1 %; none without points.
  std::optional<double> percentile(double fraction) const;

 private:
  double log_min_, log_step_;
  std::vector<std::uint64_t> bins_;
  std::uint64_t frames_ = 0, points_ = 0, pixels_ = 0;
};

}  // namespace kestrel::stereo
