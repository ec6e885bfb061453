#include "kestrel/guidance/intercept.hpp"

#include <cmath>

namespace kestrel::guidance {

bool reachable(const Eigen::Vector3d& p, const Eigen::Vector3d& v, const Eigen::Vector3d& goal, double tau,
               const FlightLimits& limits) {
  if (tau <= 0.0) return (goal - p).norm() < 1e-9;
  const bool by_acceleration = (goal - (p + v * tau)).norm() <= 0.5 * limits.max_acceleration * tau * tau;
  const bool by_speed = (goal - p).norm() <= limits.max_speed * tau;
  return by_acceleration && by_speed;
}

std::optional<InterceptPlan> earliest_intercept(const Eigen::Vector3d& p, const Eigen::Vector3d& v,
                                                const std::function<InterceptPlan(double)>& goal_at,
                                                const FlightLimits& limits, double horizon_s, double step_s) {
  const int steps = static_cast<int>(std::floor(horizon_s / step_s + 1e-9));
  for (int i = 1; i <= steps; ++i) {
    const double tau = i * step_s;
    InterceptPlan plan = goal_at(tau);
    if (reachable(p, v, plan.point, tau, limits)) {
      plan.time_s = tau;
      return plan;
    }
  }
  return std::nullopt;
}

Eigen::Vector3d rendezvous_acceleration(const Eigen::Vector3d& p, const Eigen::Vector3d& v, const Eigen::Vector3d& goal,
                                        const Eigen::Vector3d& goal_velocity, double tau) {
  const Eigen::Vector3d zem = goal - (p + v * tau);
  const Eigen::Vector3d zev = goal_velocity - v;
  return 6.0 * zem / (tau * tau) - 2.0 * zev / tau;
}

}  // namespace kestrel::guidance
