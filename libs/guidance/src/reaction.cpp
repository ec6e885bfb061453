#include "kestrel/guidance/reaction.hpp"

#include <algorithm>
#include <cmath>

#include "kestrel/guidance/target_futures.hpp"

namespace kestrel::guidance {

namespace {

Eigen::Vector3d limited(const Eigen::Vector3d& v, double limit) {
  const double n = v.norm();
  return n > limit && n > 0.0 ? Eigen::Vector3d(v * (limit / n)) : v;
}

}  // namespace

Eigen::Vector3d reaction_acceleration(const ReactionConfig& config, const Eigen::Vector3d& position,
                                      const Eigen::Vector3d& velocity, const Eigen::Vector3d& hunter) {
  const Eigen::Vector3d away = position - hunter;
  const double range = away.norm();
  if (range >= config.radius_m || range < 1e-6) return Eigen::Vector3d::Zero();
  const Eigen::Vector3d wanted = std::max(config.speed_m_s, velocity.norm()) * away / range;
  return limited((wanted - velocity) / std::max(config.response_s, 1e-3), config.acceleration_m_s2);
}

ReactionBelief::ReactionBelief(ReactionConfig config) : cfg_(config) {}

void ReactionBelief::reset() { weight_.reset(); }

double ReactionBelief::probability() const { return weight_.probability(); }

void ReactionBelief::observe(double dt, const Eigen::Vector3d& position, const Eigen::Vector3d& velocity,
                             const Eigen::Vector3d& hunter) {
  if (!weight_.active() || dt <= 0.0) return;
  weight_.fade(std::exp(-dt / cfg_.memory_s));
  const Eigen::Vector3d away = position - hunter;
  const double range = away.norm();
  if (range < cfg_.radius_m && range > 1e-6) {
    // How much it moves away: the cosine of its heading off the line from the hunter, a slow
    // target's counted at the least speed a reacting one flies (hovering is not fleeing).
    const double along = std::clamp(velocity.dot(away / range) / std::max(velocity.norm(), cfg_.speed_m_s), -1.0, 1.0);
    // Reacting: density k exp(k (c - 1)) / (1 - exp(-2k)) on [-1, 1]; not: 1/2 (any direction).
    const double k = cfg_.concentration;
    const double ratio = std::log(2.0 * k / (1.0 - std::exp(-2.0 * k))) + k * (along - 1.0);
    weight_.add(dt / cfg_.evidence_time_s * ratio);
  }
}

TargetFutures reacting_futures(const TargetFutures& futures, const ReactionConfig& config, const HunterPath& hunter,
                               std::size_t stride) {
  TargetFutures out;
  out.step_s = futures.step_s;
  const double h = futures.step_s;
  constexpr int kSubsteps = 2;  // the response is a quarter second: finer than the grid
  for (std::size_t i = 0; i < futures.size(); i += std::max<std::size_t>(stride, 1)) {
    const Eigen::Matrix3Xd& own = futures.paths[i];
    const Eigen::Index n = own.cols();
    Eigen::Matrix3Xd path(3, n);
    Eigen::Vector3d p = own.col(0);
    Eigen::Vector3d v = n > 1 ? Eigen::Vector3d((own.col(1) - own.col(0)) / h) : Eigen::Vector3d::Zero();
    path.col(0) = p;
    for (Eigen::Index k = 1; k < n; ++k) {
      const Eigen::Vector3d own_velocity = (own.col(k) - own.col(k - 1)) / h;
      for (int sub = 0; sub < kSubsteps; ++sub) {
        const double s = h * (static_cast<double>(k - 1) + static_cast<double>(sub) / kSubsteps);
        const Eigen::Vector3d near = hunter(s);
        // Within the radius it flees; beyond it, it follows its own motion again.
        const Eigen::Vector3d a =
            (p - near).norm() < config.radius_m
                ? reaction_acceleration(config, p, v, near)
                : limited((own_velocity - v) / std::max(config.response_s, 1e-3), config.acceleration_m_s2);
        const double ds = h / kSubsteps;
        p += v * ds + 0.5 * a * ds * ds;
        v += a * ds;
      }
      path.col(k) = p;
    }
    out.paths.push_back(std::move(path));
  }
  return out;
}

}  // namespace kestrel::guidance
