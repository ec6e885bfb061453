#include "fire_decision.hpp"

#include <algorithm>
#include <cmath>
#include <kestrel/geometry/frames.hpp>
#include <limits>

namespace kestrel::aim {

double predicted_miss(const net::NetModel& net, const geometry::CameraPose& launcher,
                      const Eigen::Vector3d& launcher_velocity, const TargetMotion& target) {
  const net::NetShot shot = net.fire(0.0, launcher, launcher_velocity);
  const auto& p = net.params();
  // The open window in steps of at most 10 ms: the net moves a few centimetres per step.
  const int steps = std::max(1, static_cast<int>(std::ceil(p.open_for_s / 0.01)));
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= steps; ++i) {
    const double tau = p.flight_time_s + p.open_for_s * i / steps;
    best = std::min(best, (net.position(shot, tau) - target.at(tau)).norm());
  }
  return best;
}

FireTrigger::FireTrigger(double capture_radius_m, double dwell_s, double cooldown_s)
    : radius_(capture_radius_m), dwell_(dwell_s), cooldown_(cooldown_s) {}

bool FireTrigger::update(double t, std::optional<double> miss_m, double radius_m) {
  if (!miss_m || !(*miss_m <= radius_m)) {
    within_since_ = -1.0;
    return false;
  }
  if (within_since_ < 0.0) within_since_ = t;
  if (t - within_since_ + 1e-9 < dwell_ || t - last_fire_ + 1e-9 < cooldown_) return false;
  last_fire_ = t;
  within_since_ = -1.0;  // a new shot needs a new dwell
  return true;
}

}  // namespace kestrel::aim
