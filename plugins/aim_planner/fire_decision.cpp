#include "fire_decision.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <kestrel/geometry/frames.hpp>
#include <limits>
#include <vector>

namespace kestrel::aim {

PredictedShot predict_shot(const net::NetModel& net, const geometry::CameraPose& launcher,
                           const Eigen::Vector3d& launcher_velocity,
                           const std::function<Eigen::Vector3d(double)>& target_at) {
  const net::NetShot shot = net.fire(0.0, launcher, launcher_velocity);
  const auto& p = net.params();
  // The open window in steps of at most 10 ms: the net moves a few centimetres per step.
  const int steps = std::max(1, static_cast<int>(std::ceil(p.open_for_s / 0.01)));
  PredictedShot best{0.0, Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), {}};
  best.path.reserve(steps + 1);
  for (int i = 0; i <= steps; ++i) {
    const double tau = p.flight_time_s + p.open_for_s * i / steps;
    const Eigen::Vector3d miss = target_at(tau) - net.position(shot, tau);
    best.path.push_back({tau, miss});
    if (miss.squaredNorm() < best.miss.squaredNorm()) {
      best.time_s = tau;
      best.miss = miss;
    }
  }
  return best;
}

namespace {
// Standard normal points from a fixed stream: splitmix64 for uniform numbers, Box-Muller for
// the normal ones. Written out, not std::normal_distribution, whose output the standard leaves
// to each library.
using NormalDraw = Eigen::Matrix<double, 9, 1>;  // position, velocity, unforeseen acceleration

const std::vector<NormalDraw>& standard_normal_draws() {
  static const std::vector<NormalDraw> draws = [] {
    std::uint64_t state = 0x6b657374726c;
    auto uniform = [&] {
      std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
      z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
      z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
      z ^= z >> 31;
      return (static_cast<double>(z >> 11) + 0.5) * 0x1.0p-53;  // in (0, 1)
    };
    std::vector<double> normals;
    while (normals.size() < 9 * 2048) {
      const double radius = std::sqrt(-2.0 * std::log(uniform())), angle = 2.0 * M_PI * uniform();
      normals.push_back(radius * std::cos(angle));
      normals.push_back(radius * std::sin(angle));
    }
    std::vector<NormalDraw> out(2048);
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = Eigen::Map<const NormalDraw>(normals.data() + 9 * i);
    return out;
  }();
  return draws;
}
}  // namespace

double hit_probability(const PredictedShot& shot, const ShotUncertainty& uncertainty, double radius_m) {
  const auto& covariance = uncertainty.position_velocity;
  if (shot.path.empty() || !covariance.allFinite() || !std::isfinite(uncertainty.lead_s) ||
      !uncertainty.acceleration_m_s2.allFinite() || !std::isfinite(uncertainty.manoeuvre_m_s2))
    return 0.0;
  for (const MissAt& m : shot.path)
    if (!m.miss.allFinite() || !std::isfinite(m.tau_s)) return 0.0;
  // A square root of the covariance that survives a covariance not quite positive definite.
  using Matrix6 = Eigen::Matrix<double, 6, 6>;
  const Eigen::SelfAdjointEigenSolver<Matrix6> eigen(0.5 * (covariance + covariance.transpose()));
  const Matrix6 root = eigen.eigenvectors() * eigen.eigenvalues().cwiseMax(0.0).cwiseSqrt().asDiagonal();
  const double radius_squared = radius_m * radius_m;
  std::size_t inside = 0;
  for (const NormalDraw& z : standard_normal_draws()) {
    const Eigen::Matrix<double, 6, 1> state = root * z.head<6>();
    const Eigen::Vector3d acceleration = uncertainty.acceleration_m_s2 + uncertainty.manoeuvre_m_s2 * z.tail<3>();
    for (const MissAt& m : shot.path) {
      const double s = uncertainty.lead_s + m.tau_s;
      const Eigen::Vector3d off = m.miss + state.head<3>() + state.tail<3>() * s + 0.5 * s * s * acceleration;
      if (off.squaredNorm() <= radius_squared) {
        ++inside;
        break;
      }
    }
  }
  return static_cast<double>(inside) / static_cast<double>(standard_normal_draws().size());
}

FireTrigger::FireTrigger(double capture_radius_m, double dwell_s, double cooldown_s)
    : radius_(capture_radius_m), dwell_(dwell_s), cooldown_(cooldown_s) {}

bool FireTrigger::decide(double t, bool good_shot) {
  if (!good_shot) {
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
