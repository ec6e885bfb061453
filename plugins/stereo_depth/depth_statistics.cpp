#include "depth_statistics.hpp"

#include <algorithm>
#include <cmath>

namespace kestrel::stereo {

DepthStatistics::DepthStatistics(double min_depth_m, double max_depth_m)
    : log_min_(std::log(min_depth_m)), log_step_(std::log(1.01)) {
  const double span = std::max(0.0, std::log(max_depth_m) - log_min_);
  bins_.assign(static_cast<std::size_t>(std::ceil(span / log_step_)) + 1, 0);
}

void DepthStatistics::add_frame(const pcl::PointCloud<pcl::PointXYZ>& points, std::uint64_t pixels) {
  ++frames_;
  pixels_ += pixels;
  const double last = static_cast<double>(bins_.size() - 1);
  for (const auto& p : points) {
    if (!(p.z > 0.0f)) continue;  // not a depth (NaN or behind the camera)
    ++points_;
    const double bin = std::clamp(std::floor((std::log(p.z) - log_min_) / log_step_), 0.0, last);
    ++bins_[static_cast<std::size_t>(bin)];
  }
}

std::optional<double> DepthStatistics::percentile(double fraction) const {
  if (points_ == 0) return std::nullopt;
  const double wanted = std::clamp(fraction, 0.0, 1.0) * static_cast<double>(points_);
  std::uint64_t below = 0;
  for (std::size_t i = 0; i < bins_.size(); ++i) {
    below += bins_[i];
    if (static_cast<double>(below) >= wanted && bins_[i] > 0)
      return std::exp(log_min_ + (static_cast<double>(i) + 0.5) * log_step_);  // the bin's middle
  }
  return std::exp(log_min_ + (static_cast<double>(bins_.size()) - 0.5) * log_step_);
}

}  // namespace kestrel::stereo
