#include "oscillation.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <limits>

namespace kestrel::aim {

namespace {
// Least squares of z on the three columns of X (n x 3): the mean squared residual and the
// coefficients, or none where X's columns are (nearly) dependent.
std::optional<std::pair<double, Eigen::Vector3d>> least_squares(const Eigen::MatrixX3d& x, const Eigen::VectorXd& z) {
  const Eigen::Matrix3d normal = x.transpose() * x;
  const Eigen::LDLT<Eigen::Matrix3d> ldlt(normal);
  if (ldlt.info() != Eigen::Success || !(ldlt.vectorD().array() > 1e-9 * normal.trace()).all()) return std::nullopt;
  const Eigen::Vector3d coefficients = ldlt.solve(x.transpose() * z);
  return std::pair{(z - x * coefficients).squaredNorm() / static_cast<double>(z.size()), coefficients};
}
}  // namespace

OscillationPredictor::OscillationPredictor(const OscillationConfig& config) : cfg_(config) {}

void OscillationPredictor::add(double t, const Eigen::Vector3d& sighting) {
  window_.push_back({t, sighting});
  while (window_.front().t < t - cfg_.window_s) window_.pop_front();
  fit();
}

void OscillationPredictor::fit() {
  axes_ = {};
  const auto n = static_cast<Eigen::Index>(window_.size());
  if (n < cfg_.min_sightings) return;
  const double t_ref = window_.back().t;
  Eigen::VectorXd s(n);  // time from the newest sighting (<= 0)
  Eigen::MatrixX3d positions(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) {
    s[i] = window_[static_cast<std::size_t>(i)].t - t_ref;
    positions.row(i) = window_[static_cast<std::size_t>(i)].position.transpose();
  }
  // The parabola each axis is judged against: constant acceleration over the window.
  Eigen::MatrixX3d parabola(n, 3);
  parabola << Eigen::VectorXd::Ones(n), s, s.array().square().matrix();
  std::array<double, 3> parabola_residual{};
  for (int axis = 0; axis < 3; ++axis) {
    const auto fit = least_squares(parabola, positions.col(axis));
    parabola_residual[axis] = fit ? fit->first : std::numeric_limits<double>::infinity();
  }
  // The sinusoid: for each omega on a geometric grid (4 % apart), c, A and B by least squares, then
  // a finer grid (0.5 %) about the best.
  std::array<std::optional<AxisOscillation>, 3> best;
  Eigen::MatrixX3d sinusoid(n, 3);
  sinusoid.col(0).setOnes();
  const auto try_omega = [&](int axis, double omega) {
    sinusoid.col(1) = (omega * s).array().cos().matrix();
    sinusoid.col(2) = (omega * s).array().sin().matrix();
    const auto fit = least_squares(sinusoid, positions.col(axis));
    if (!fit) return;
    const double rms = std::sqrt(fit->first);
    if (!best[axis] || rms < best[axis]->rms_residual_m)
      best[axis] = AxisOscillation{fit->second[0], fit->second[1], fit->second[2], omega, rms};
  };
  for (int axis = 0; axis < 3; ++axis) {
    // A parabola within 5 mm leaves nothing to explain (a still or straight axis, no noise).
    if (parabola_residual[axis] < 0.005 * 0.005) continue;
    for (double omega = cfg_.min_omega_rad_s; omega <= cfg_.max_omega_rad_s; omega *= 1.04) try_omega(axis, omega);
    if (!best[axis]) continue;
    const double coarse = best[axis]->omega_rad_s;
    for (int step = -7; step <= 7; ++step)
      if (step != 0)
        try_omega(axis, std::clamp(coarse * (1.0 + 0.005 * step), cfg_.min_omega_rad_s, cfg_.max_omega_rad_s));
    const double rms = best[axis]->rms_residual_m;
    if (rms * rms * cfg_.min_improvement < parabola_residual[axis]) axes_[axis] = best[axis];
  }
}

double OscillationPredictor::position_after(const AxisOscillation& axis, double tau) {
  return axis.centre + axis.a * std::cos(axis.omega_rad_s * tau) + axis.b * std::sin(axis.omega_rad_s * tau);
}

}  // namespace kestrel::aim
