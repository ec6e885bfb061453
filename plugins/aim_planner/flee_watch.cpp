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
  if (fleeing_for_s_ >= cfg_.time_s && !own_path_) evader_ = true;
  if (evader_ && cfg_.calm_speed_m_s > 0.0 && range > cfg_.max_range_m) {
    restless_s_ = std::max(0.0, restless_s_ + (target_velocity.norm() > cfg_.calm_speed_m_s ? dt : -dt));
    if (restless_s_ >= cfg_.calm_time_s) {
      own_path_ = true;
      evader_ = false;
    }
  }
}

void FleeWatch::reset() {
  fleeing_for_s_ = 0.0;
  restless_s_ = 0.0;
  evader_ = own_path_ = false;
}

}  // namespace kestrel::aim
