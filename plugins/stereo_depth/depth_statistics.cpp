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
  constexpr std::size_t kStride = 16;
  points_ += points.size();
  std::size_t i = until_sample_;
  for (; i < points.size(); i += kStride) {
    const float z = points[i].z;
    if (!(z > 0.0f)) continue;  // not a depth (NaN or behind the camera)
    const double bin = std::clamp(std::floor((std::log(z) - log_min_) / log_step_), 0.0, last);
    ++bins_[static_cast<std::size_t>(bin)];
    ++binned_;
  }
  until_sample_ = static_cast<std::uint32_t>(i - points.size());  // carried into the next frame
}

std::optional<double> DepthStatistics::percentile(double fraction) const {
  if (binned_ == 0) return std::nullopt;
  const double wanted = std::clamp(fraction, 0.0, 1.0) * static_cast<double>(binned_);
  std::uint64_t below = 0;
  for (std::size_t i = 0; i < bins_.size(); ++i) {
    below += bins_[i];
    if (static_cast<double>(below) >= wanted && bins_[i] > 0)
      return std::exp(log_min_ + (static_cast<double>(i) + 0.5) * log_step_);  // the bin's middle
  }
  return std::exp(log_min_ + (static_cast<double>(bins_.size()) - 0.5) * log_step_);
}

}  // namespace kestrel::stereo
