#include "oscillation.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <limits>

namespace kestrel::aim {

namespace {
// Least squares on the three columns of X (n x 3), factorised once for every right-hand side that
// shares them (the three axes at one angular frequency).
class LeastSquares {
 public:
  explicit LeastSquares(const Eigen::MatrixX3d& x) : x_(x), normal_(x.transpose() * x), ldlt_(normal_) {
    solvable_ = ldlt_.info() == Eigen::Success && (ldlt_.vectorD().array() > 1e-9 * normal_.trace()).all();
  }
  // The mean squared residual of z and the coefficients, or none where X's columns are (nearly)
  // dependent.
  std::optional<std::pair<double, Eigen::Vector3d>> fit(const Eigen::VectorXd& z) const {
    if (!solvable_) return std::nullopt;
    const Eigen::Vector3d coefficients = ldlt_.solve(x_.transpose() * z);
    return std::pair{(z - x_ * coefficients).squaredNorm() / static_cast<double>(z.size()), coefficients};
  }

 private:
  const Eigen::MatrixX3d& x_;
  Eigen::Matrix3d normal_;
  Eigen::LDLT<Eigen::Matrix3d> ldlt_;
  bool solvable_ = false;
};
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
  const LeastSquares parabola_fit(parabola);
  for (int axis = 0; axis < 3; ++axis) {
    const auto fit = parabola_fit.fit(positions.col(axis));
    parabola_residual[axis] = fit ? fit->first : std::numeric_limits<double>::infinity();
  }
  // A parabola within 5 mm leaves nothing to explain (a still or straight axis, no noise).
  std::array<bool, 3> to_fit{};
  for (int axis = 0; axis < 3; ++axis) to_fit[axis] = parabola_residual[axis] >= 0.005 * 0.005;
  // The sinusoid: for each omega on a geometric grid (4 % apart), c, A and B by least squares, then
  // a finer grid (0.5 %) about each axis's best.
  std::array<std::optional<AxisOscillation>, 3> best;
  Eigen::MatrixX3d sinusoid(n, 3);
  sinusoid.col(0).setOnes();
  const auto try_omega = [&](double omega, const std::array<bool, 3>& axes) {
    sinusoid.col(1) = (omega * s).array().cos().matrix();
    sinusoid.col(2) = (omega * s).array().sin().matrix();
    const LeastSquares sinusoid_fit(sinusoid);
    for (int axis = 0; axis < 3; ++axis) {
      if (!axes[axis]) continue;
      const auto fit = sinusoid_fit.fit(positions.col(axis));
      if (!fit) continue;
      const double rms = std::sqrt(fit->first);
      if (!best[axis] || rms < best[axis]->rms_residual_m)
        best[axis] = AxisOscillation{fit->second[0], fit->second[1], fit->second[2], omega, rms};
    }
  };
  if (!(to_fit[0] || to_fit[1] || to_fit[2])) return;
  for (double omega = cfg_.min_omega_rad_s; omega <= cfg_.max_omega_rad_s; omega *= 1.04) try_omega(omega, to_fit);
  for (int axis = 0; axis < 3; ++axis) {
    if (!to_fit[axis] || !best[axis]) continue;
    std::array<bool, 3> only{};
    only[axis] = true;
    const double coarse = best[axis]->omega_rad_s;
    for (int step = -7; step <= 7; ++step)
      if (step != 0)
        try_omega(std::clamp(coarse * (1.0 + 0.005 * step), cfg_.min_omega_rad_s, cfg_.max_omega_rad_s), only);
    const double rms = best[axis]->rms_residual_m;
    if (rms * rms * cfg_.min_improvement < parabola_residual[axis]) axes_[axis] = best[axis];
  }
}

double OscillationPredictor::position_after(const AxisOscillation& axis, double tau) {
  return axis.centre + axis.a * std::cos(axis.omega_rad_s * tau) + axis.b * std::sin(axis.omega_rad_s * tau);
}

Eigen::Vector3d OscillationPredictor::predict(double tau, Eigen::Vector3d elsewhere) const {
  for (int axis = 0; axis < 3; ++axis)
    if (const auto& o = axes_[axis]) elsewhere[axis] = position_after(*o, tau);
  return elsewhere;
}

SwingAim swing_centre_aim(const OscillationPredictor& oscillation, const Eigen::Vector3d& position,
                          const Eigen::Vector3d& velocity, const SwingBounds& bounds) {
  SwingAim aim{position, velocity, {}};
  const auto fitted = [&](const std::optional<AxisOscillation>& o) {
    return o && std::hypot(o->a, o->b) <= bounds.max_amplitude_m && o->rms_residual_m <= bounds.max_residual_m;
  };
  const bool wide = std::any_of(oscillation.axes().begin(), oscillation.axes().end(), [&](const auto& o) {
    return fitted(o) && std::hypot(o->a, o->b) >= bounds.min_amplitude_m;
  });
  if (!wide) return aim;
  double peak_speed_squared = 0.0;
  for (const auto& o : oscillation.axes())
    if (fitted(o)) peak_speed_squared += std::pow(std::hypot(o->a, o->b) * o->omega_rad_s, 2);
  if (std::sqrt(peak_speed_squared) > bounds.max_speed_m_s) return aim;
  // A swing wide enough to wait for: wait at its centre on every axis that swings, the narrow ones
  // too. A line flown obliquely, or a figure-8, passes through the centre of each of its swings at
  // once; an axis left following its narrow swing lags it, and the net, by up to that swing.
  for (int axis = 0; axis < 3; ++axis) {
    const auto& o = oscillation.axes()[axis];
    if (!fitted(o)) continue;
    aim.position[axis] = o->centre;
    aim.velocity[axis] = 0.0;
    aim.waiting[axis] = true;
  }
  return aim;
}

}  // namespace kestrel::aim
