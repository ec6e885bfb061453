#include "flee_watch.hpp"

#include <algorithm>

namespace kestrel::aim {

void FleeWatch::update(double dt, const Eigen::Vector3d& target, const Eigen::Vector3d& target_velocity,
                       const Eigen::Vector3d& hunter, const Eigen::Vector3d& hunter_velocity) {
  const Eigen::Vector3d line_of_sight = target - hunter;
  const double range = line_of_sight.norm();
  if (range < 1e-6) return;
  const double away = target_velocity.dot(line_of_sight) / range;
  const double closing = hunter_velocity.dot(line_of_sight) / range;
  const bool flees = range <= cfg_.max_range_m && closing >= cfg_.min_closing_m_s &&
                     away >= std::max(cfg_.min_speed_m_s, cfg_.min_share * target_velocity.norm());
  fleeing_for_s_ = flees ? fleeing_for_s_ + dt : 0.0;
  if (fleeing_for_s_ >= cfg_.time_s) evader_ = true;
}

void FleeWatch::reset() {
  fleeing_for_s_ = 0.0;
  evader_ = false;
}

}  // namespace kestrel::aim
