#include "trajectory.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "kestrel/error.hpp"

namespace kestrel::intruder {

FigureEight::FigureEight(const geometry::CameraPose& camera, double distance, double half_width, double half_height,
                         double period)
    : camera_(camera),
      distance_(distance),
      half_width_(half_width),
      half_height_(half_height),
      omega_(2.0 * M_PI / period) {}

State FigureEight::at(double t) const {
  const double w = omega_;
  const Eigen::Vector3d p_cam(half_width_ * std::sin(w * t), half_height_ * std::sin(2 * w * t), distance_);
  const Eigen::Vector3d v_cam(half_width_ * w * std::cos(w * t), 2 * w * half_height_ * std::cos(2 * w * t), 0.0);
  return State{camera_.to_world(p_cam), camera_.world_from_camera() * v_cam};
}

StraightLine::StraightLine(const Eigen::Vector3d& start, const Eigen::Vector3d& end, double speed, bool bounce,
                           double acceleration)
    : start_(start), length_((end - start).norm()), speed_(speed), bounce_(bounce), acceleration_(acceleration) {
  direction_ = length_ > 0 ? Eigen::Vector3d((end - start) / length_) : Eigen::Vector3d::Zero();
  if (acceleration_ > 0 && speed_ > 0) {
    // Up to speed over v^2 / 2a, unless half the line comes first.
    top_speed_ = std::min(speed_, std::sqrt(acceleration_ * length_));
    const double ramp = top_speed_ * top_speed_ / acceleration_;  // both ramps' length
    pass_time_ = 2.0 * top_speed_ / acceleration_ + (length_ - ramp) / top_speed_;
  }
}

std::pair<double, double> StraightLine::pass(double tau) const {
  const double a = acceleration_, v = top_speed_, ramp_time = v / a;
  if (tau <= ramp_time) return {0.5 * a * tau * tau, a * tau};
  const double left = pass_time_ - tau;
  if (left <= ramp_time) return {length_ - 0.5 * a * left * left, a * left};
  return {0.5 * v * ramp_time + v * (tau - ramp_time), v};
}

State StraightLine::at(double t) const {
  if (length_ <= 0 || speed_ <= 0) return State{start_, Eigen::Vector3d::Zero()};
  if (acceleration_ > 0) {
    double tau = std::max(t, 0.0);
    double sign = 1.0;
    if (bounce_) {
      tau = std::fmod(tau, 2.0 * pass_time_);
      if (tau > pass_time_) {
        tau -= pass_time_;
        sign = -1.0;  // on the way back
      }
    } else if (tau >= pass_time_) {
      return State{start_ + direction_ * length_, Eigen::Vector3d::Zero()};
    }
    const auto [s, speed] = pass(tau);
    return sign > 0 ? State{start_ + direction_ * s, direction_ * speed}
                    : State{start_ + direction_ * (length_ - s), -direction_ * speed};
  }
  double s = speed_ * std::max(t, 0.0);
  double sign = 1.0;
  if (bounce_) {
    const double lap = std::fmod(s, 2.0 * length_);
    if (lap > length_) {
      s = 2.0 * length_ - lap;
      sign = -1.0;
    } else {
      s = lap;
    }
  } else if (s >= length_) {
    return State{start_ + direction_ * length_, Eigen::Vector3d::Zero()};
  }
  return State{start_ + direction_ * s, direction_ * speed_ * sign};
}

namespace {
constexpr double kJinkStep = 0.01;  // s: the grid the jinks are integrated on
}

Jink::Jink(const Eigen::Vector3d& centre, const Eigen::Vector3d& half_extent, double speed, double max_acceleration,
           double min_hold, double max_hold, std::uint64_t seed)
    : centre_(centre),
      half_extent_(half_extent),
      speed_(speed),
      max_acceleration_(max_acceleration),
      min_hold_(min_hold),
      max_hold_(std::max(min_hold, max_hold)),
      rng_(seed) {
  // It starts at the centre, cruising across the box's long horizontal side.
  const Eigen::Vector3d heading =
      half_extent.y() >= half_extent.x() ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitX();
  samples_.push_back({State{centre, heading * speed}, Eigen::Vector3d::Zero()});
}

void Jink::extend_to(std::size_t k) const {
  std::uniform_real_distribution<double> hold(min_hold_, max_hold_);
  std::uniform_int_distribution<int> sign(-1, 1);  // left, straight, right; down, level, up
  while (samples_.size() <= k) {
    Sample& last = samples_.back();
    const double t = kJinkStep * static_cast<double>(samples_.size() - 1);
    const State& s = last.state;
    if (t >= hold_until_) {
      lateral_ = sign(rng_);
      vertical_ = sign(rng_);
      hold_until_ = t + hold(rng_);
    }
    // Outside its box it heads back: towards the centre horizontally, and vertically.
    const Eigen::Vector3d off = s.position - centre_;
    Eigen::Vector3d horizontal_velocity(s.velocity.x(), s.velocity.y(), 0.0);
    const Eigen::Vector3d left = Eigen::Vector3d::UnitZ().cross(horizontal_velocity).normalized();
    double lateral = lateral_, vertical = vertical_;
    if (std::abs(off.x()) > half_extent_.x() || std::abs(off.y()) > half_extent_.y())
      if (off.head<2>().dot(horizontal_velocity.head<2>()) > 0.0) lateral = left.dot(-off) >= 0.0 ? 1.0 : -1.0;
    if (off.z() > half_extent_.z()) vertical = -1.0;
    if (off.z() < -half_extent_.z()) vertical = 1.0;
    Eigen::Vector3d a = lateral * max_acceleration_ * left;
    a.z() = vertical * max_acceleration_;
    // The climb rate stays within half the speed.
    const double max_climb = 0.5 * speed_;
    a.z() = std::clamp(a.z(), (-max_climb - s.velocity.z()) / kJinkStep, (max_climb - s.velocity.z()) / kJinkStep);
    last.acceleration = a;
    State next;
    next.position = s.position + s.velocity * kJinkStep + 0.5 * a * kJinkStep * kJinkStep;
    next.velocity = s.velocity + a * kJinkStep;
    // A turn keeps the horizontal speed that the climb leaves.
    const double vz = std::clamp(next.velocity.z(), -max_climb, max_climb);
    Eigen::Vector2d vh = next.velocity.head<2>();
    vh *= std::sqrt(std::max(0.0, speed_ * speed_ - vz * vz)) / std::max(vh.norm(), 1e-9);
    next.velocity = Eigen::Vector3d(vh.x(), vh.y(), vz);
    samples_.push_back({next, Eigen::Vector3d::Zero()});
  }
}

State Jink::at(double t) const {
  // Integrated on demand and kept: an hour is 360,000 samples (30 MB), the most it keeps.
  if (t > 3600.0) throw Error("jink: the flight lasts at most 3600 s (asked for " + std::to_string(t) + " s)");
  const double clamped = std::max(0.0, t);
  const auto k = static_cast<std::size_t>(clamped / kJinkStep);
  extend_to(k + 1);
  const Sample& s = samples_[k];
  const double tau = clamped - kJinkStep * static_cast<double>(k);
  return State{s.state.position + s.state.velocity * tau + 0.5 * s.acceleration * tau * tau,
               s.state.velocity + s.acceleration * tau};
}

RandomManoeuvre::RandomManoeuvre(const Eigen::Vector3d& centre, const Eigen::Vector3d& half_extent, double max_speed,
                                 std::uint64_t seed, double max_acceleration, double max_frequency_hz)
    : centre_(centre) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> frequency(0.03, std::max(0.03, max_frequency_hz));  // Hz
  std::uniform_real_distribution<double> phase(0.0, 2.0 * M_PI);
  std::uniform_real_distribution<double> weight(0.3, 1.0);
  constexpr int kWaves = 3;
  for (int axis = 0; axis < 3; ++axis) {
    double weights = 0.0;
    for (int k = 0; k < kWaves; ++k) {
      waves_[axis].push_back({weight(rng), 2.0 * M_PI * frequency(rng), phase(rng)});
      weights += waves_[axis].back().amplitude;
    }
    // Scale so the sum can never leave the box, then so the speed bound |v| <= sum(a w) and the
    // acceleration bound |a| <= sum(a w^2) hold: a third of each limit's square per axis.
    double speed_bound = 0.0, acceleration_bound = 0.0;
    for (auto& w : waves_[axis]) {
      w.amplitude *= half_extent[axis] / weights;
      speed_bound += w.amplitude * w.omega;
      acceleration_bound += w.amplitude * w.omega * w.omega;
    }
    double scale = 1.0;
    if (const double limit = max_speed / std::sqrt(3.0); speed_bound > limit) scale = limit / speed_bound;
    if (const double limit = max_acceleration / std::sqrt(3.0);
        max_acceleration > 0 && acceleration_bound * scale > limit)
      scale = limit / acceleration_bound;
    for (auto& w : waves_[axis]) w.amplitude *= scale;
  }
}

State RandomManoeuvre::at(double t) const {
  State s{centre_, Eigen::Vector3d::Zero()};
  for (int axis = 0; axis < 3; ++axis) {
    for (const auto& w : waves_[axis]) {
      s.position[axis] += w.amplitude * std::sin(w.omega * t + w.phase);
      s.velocity[axis] += w.amplitude * w.omega * std::cos(w.omega * t + w.phase);
    }
  }
  return s;
}

RecordedFlight::RecordedFlight(const std::filesystem::path& csv, bool loop) : loop_(loop) {
  std::ifstream in(csv);
  if (!in) throw Error("cannot open trajectory file " + csv.string());
  read(in, csv.string());
}

RecordedFlight::RecordedFlight(std::istream& csv, const std::string& label, bool loop) : loop_(loop) {
  read(csv, label);
}

void RecordedFlight::read(std::istream& in, const std::string& label) {
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty() || line[0] == '#') continue;
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream fields(line);
    double t, x, y, z;
    if (!(fields >> t >> x >> y >> z)) {
      if (times_.empty() && number == 1) continue;  // the header
      throw Error(SourceLocation{label, number, 0}, "expected four numbers: t,x,y,z");
    }
    if (!times_.empty() && t <= times_.back()) throw Error(SourceLocation{label, number, 0}, "times must increase");
    // Numbers a double holds can still overflow once subtracted: the flight's duration and each
    // segment's speed must stay finite, or at() would return infinities and NaNs.
    if (!times_.empty() && !std::isfinite(t - times_.front()))
      throw Error(SourceLocation{label, number, 0}, "the time is too far from the first row's: the duration overflows");
    if (!times_.empty() && !((Eigen::Vector3d(x, y, z) - points_.back()) / (t - times_.back())).allFinite())
      throw Error(SourceLocation{label, number, 0},
                  "the step from the previous row is too large for its time: the speed is not finite");
    times_.push_back(t);
    points_.emplace_back(x, y, z);
  }
  if (times_.size() < 2) throw Error("trajectory file " + label + " needs at least two rows of t,x,y,z");
}

State RecordedFlight::at(double t) const {
  const double t0 = times_.front();
  double local = t + t0;  // the file's clock starts at its first row
  if (loop_) local = t0 + std::fmod(std::max(t, 0.0), duration());
  if (!(local > times_.front())) return State{points_.front(), Eigen::Vector3d::Zero()};  // NaN too
  if (local >= times_.back()) return State{points_.back(), Eigen::Vector3d::Zero()};
  const auto hi = static_cast<std::size_t>(std::upper_bound(times_.begin(), times_.end(), local) - times_.begin());
  const std::size_t lo = hi - 1;
  const double span = times_[hi] - times_[lo];
  const double f = (local - times_[lo]) / span;
  return State{points_[lo] + f * (points_[hi] - points_[lo]), (points_[hi] - points_[lo]) / span};
}

Placed::Placed(std::unique_ptr<Trajectory> inner, const Eigen::Vector3d& offset, double yaw, double time_scale)
    : inner_(std::move(inner)),
      rotation_(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix()),
      offset_(offset),
      time_scale_(time_scale) {}

State Placed::at(double t) const {
  const State s = inner_->at(time_scale_ * t);
  return {rotation_ * s.position + offset_, time_scale_ * (rotation_ * s.velocity)};
}

}  // namespace kestrel::intruder
