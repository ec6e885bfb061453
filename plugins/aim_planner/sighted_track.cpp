#include "sighted_track.hpp"

#include <limits>

namespace kestrel::aim {

const msg::Track* sighted_track(const msg::Tracks& tracks, const geometry::CameraPose& camera, double min_height_m,
                                const Eigen::Vector3d& predicted,
                                const std::function<bool(const Eigen::Vector3d&)>& expected) {
  const msg::Track* best = nullptr;
  double best_distance = std::numeric_limits<double>::infinity();
  for (const msg::Track& track : tracks.items) {
    if (track.misses > 0 || !track.detection.allFinite()) continue;
    const Eigen::Vector3d sighting = camera.to_world(track.detection);
    if (sighting.z() < min_height_m || !expected(sighting)) continue;
    if (const double d = (sighting - predicted).norm(); d < best_distance) {
      best = &track;
      best_distance = d;
    }
  }
  return best;
}

}  // namespace kestrel::aim
