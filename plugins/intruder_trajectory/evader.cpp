#include "evader.hpp"

#include <algorithm>
#include <cmath>

namespace kestrel::intruder {

namespace {
constexpr double kStep = 0.01;  // s

Eigen::Vector3d limited(const Eigen::Vector3d& v, double limit) {
  const double n = v.norm();
  return n > limit && n > 0.0 ? Eigen::Vector3d(v * (limit / n)) : v;
}
}  // namespace

Evader::Evader(const Eigen::Vector3d& start, const EvaderParams& params, std::uint64_t seed)
    : p_(params), rng_(seed), state_{start, Eigen::Vector3d::Zero()}, waypoint_(start) {}

Eigen::Vector3d Evader::back_into_box(const Eigen::Vector3d& desired) const {
  Eigen::Vector3d v = desired;
  for (int axis = 0; axis < 3; ++axis) {
    const double off = state_.position[axis] - p_.centre[axis];
    // Outside its box on this axis, and not heading back: head back at the speed it had.
    if (std::abs(off) > p_.half_extent[axis] && v[axis] * off > 0.0) v[axis] = -v[axis];
  }
  if (state_.position.z() < p_.min_height && v.z() < 0.0) v.z() = -v.z();
  return v;
}

Eigen::Vector3d Evader::desired_velocity(const std::optional<Eigen::Vector3d>& hunter) {
  const double range = hunter ? (state_.position - *hunter).norm() : INFINITY;
  const Mode before = mode_;
  mode_ = range < p_.break_radius ? Mode::break_away : range < p_.flee_radius ? Mode::flee : Mode::cruise;
  if (mode_ == Mode::cruise) {
    if ((waypoint_ - state_.position).norm() < 0.5 || before != Mode::cruise) {
      std::uniform_real_distribution<double> u(-1.0, 1.0);
      for (int axis = 0; axis < 3; ++axis) waypoint_[axis] = p_.centre[axis] + u(rng_) * p_.half_extent[axis];
      waypoint_.z() = std::max(waypoint_.z(), p_.min_height);
    }
    return limited(waypoint_ - state_.position, p_.cruise_speed);
  }
  // Away from the hunter, mostly level (climbing away would leave it no room).
  Eigen::Vector3d away = state_.position - *hunter;
  away.z() *= 0.3;
  away = away.norm() > 1e-6 ? Eigen::Vector3d(away.normalized()) : Eigen::Vector3d::UnitX();
  Eigen::Vector3d across = Eigen::Vector3d::UnitZ().cross(away);
  across = across.norm() > 1e-6 ? Eigen::Vector3d(across.normalized()) : Eigen::Vector3d::UnitY();
  if (mode_ == Mode::break_away) {
    if (before != Mode::break_away) {
      // Break to the side it already moves across the line of sight, and climb or dive at random.
      break_side_ = state_.velocity.dot(across) >= 0.0 ? 1.0 : -1.0;
      break_climb_ = std::uniform_real_distribution<double>(-0.5, 0.5)(rng_);
    }
    return p_.top_speed * (break_side_ * across + 0.3 * away + break_climb_ * Eigen::Vector3d::UnitZ()).normalized();
  }
  const double weave = std::sin(2.0 * M_PI * t_ / p_.weave_period);
  return p_.top_speed * (away + 0.6 * weave * across).normalized();
}

State Evader::step(double t, const std::optional<Eigen::Vector3d>& hunter) {
  while (t_ + kStep <= t + 1e-12) {
    const Eigen::Vector3d desired = back_into_box(desired_velocity(hunter));
    // A multirotor's response: towards the desired velocity in about a quarter second, within its
    // acceleration limit.
    const Eigen::Vector3d a = limited((desired - state_.velocity) / 0.25, p_.max_acceleration);
    state_.position += state_.velocity * kStep + 0.5 * a * kStep * kStep;
    state_.velocity = limited(state_.velocity + a * kStep, p_.top_speed);
    t_ += kStep;
  }
  return state_;
}

}  // namespace kestrel::intruder
