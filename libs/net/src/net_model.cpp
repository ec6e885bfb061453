#include "kestrel/net/net_model.hpp"

#include <algorithm>
#include <cmath>

namespace kestrel::net {

NetShot NetModel::fire(double t, const geometry::CameraPose& launcher, const Eigen::Vector3d& launcher_velocity) const {
  NetShot shot;
  shot.fired_at = t;
  shot.launch_position = launcher.position_world;
  // Reach launch + displacement after T under gravity: v0 = d / T + g T / 2 (up), plus the
  // launcher's own velocity.
  const Eigen::Vector3d displacement = launcher.world_from_camera() * p_.open_point_camera;
  const double T = p_.flight_time_s;
  shot.launch_velocity = launcher_velocity + displacement / T + Eigen::Vector3d(0.0, 0.0, 0.5 * p_.gravity * T);
  return shot;
}

Eigen::Vector3d NetModel::position(const NetShot& shot, double t) const {
  const double tau = t - shot.fired_at;
  return shot.launch_position + shot.launch_velocity * tau - Eigen::Vector3d(0.0, 0.0, 0.5 * p_.gravity * tau * tau);
}

bool NetModel::open(const NetShot& shot, double t) const {
  const double tau = t - shot.fired_at;
  return tau >= p_.flight_time_s - 1e-9 && tau <= p_.flight_time_s + p_.open_for_s + 1e-9;
}

bool NetModel::catches(const NetShot& shot, double t, const Eigen::Vector3d& target) const {
  return open(shot, t) && (position(shot, t) - target).norm() <= p_.radius_m;
}

std::optional<double> NetModel::sweep(const NetShot& shot, double t0, const Eigen::Vector3d& from, double t1,
                                      const Eigen::Vector3d& to, double& closest) const {
  constexpr double kStep = 0.002;  // s: at 10 m/s closing speed, 2 cm between checks
  const int steps = std::max(1, static_cast<int>(std::ceil((t1 - t0) / kStep)));
  for (int i = 0; i <= steps; ++i) {
    const double w = static_cast<double>(i) / steps;
    const double t = t0 + w * (t1 - t0);
    if (!open(shot, t)) continue;
    const Eigen::Vector3d target = from + w * (to - from);
    const double d = (position(shot, t) - target).norm();
    closest = std::min(closest, d);
    if (d <= p_.radius_m) return t;
  }
  return std::nullopt;
}

}  // namespace kestrel::net
