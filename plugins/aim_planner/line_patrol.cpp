#include "line_patrol.hpp"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace kestrel::aim {

double PatrolLine::distance(const Eigen::Vector3d& p, double slack_m) const {
  const Eigen::Vector3d d = p - centre;
  const double s = d.dot(direction);
  // Beyond an end where it turned, it is not on this patrol; beyond one not seen yet, the line
  // goes on.
  if ((turned[0] && s < -half_length_m - slack_m) || (turned[1] && s > half_length_m + slack_m))
    return std::numeric_limits<double>::infinity();
  return (d - s * direction).norm();
}

Eigen::Vector3d PatrolLine::predict(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity, double tau,
                                    double max_deceleration_m_s2) const {
  double s = (position - centre).dot(direction), v = velocity.dot(direction);
  const Eigen::Vector3d across = position - centre - s * direction;
  // A line is found only where a turn was seen, so its braking is known; none: no braking.
  if (tau <= 0.0 || deceleration_m_s2 <= 0.0) return position + std::max(0.0, tau) * velocity;
  // The patrol's own motion, stepped: up to its cruise, braking in time to rest at the end it
  // flies towards, and back.
  const double a = std::min(deceleration_m_s2, max_deceleration_m_s2);
  const double cruise = std::max(cruise_speed_m_s, std::abs(v));
  constexpr double kStep_s = 0.005;
  for (double t = 0.0; t < tau; t += kStep_s) {
    const double h = std::min(kStep_s, tau - t);
    const double sign = v > 0.0 || (v == 0.0 && s < 0.0) ? 1.0 : -1.0;
    const double to_end = half_length_m - sign * s;
    if (v * v >= 2.0 * a * to_end)
      v -= sign * a * h;  // braking into the turn (and, past rest, away from the end)
    else if (std::abs(v) < cruise)
      v = sign * std::min(cruise, std::abs(v) + a * h);
    s += v * h;
  }
  return centre + s * direction + across;
}

void LinePatrol::add(double t, const Eigen::Vector3d& sighting) {
  if (!sighting.allFinite()) return;
  window_.push_back({t, sighting});
  while (!window_.empty() && window_.front().t < t - cfg_.window_s) window_.pop_front();
  fit();
}

std::optional<double> LinePatrol::last_sighting_s() const {
  if (window_.empty()) return std::nullopt;
  return window_.back().t;
}

void LinePatrol::reset() {
  window_.clear();
  line_.reset();
}

void LinePatrol::fit() {
  auto line = fit_window();
  if (!line) return;
  if (line_) {
    // The direction's sign is the eigen solver's choice: kept as it was, the ends keep their indices.
    if (line->direction.dot(line_->direction) < 0.0) {
      line->direction = -line->direction;
      std::swap(line->turned[0], line->turned[1]);
    }
    line->cruise_speed_m_s = std::max(line->cruise_speed_m_s, line_->cruise_speed_m_s);
  }
  // A line once found stays until reset(): the far end's sightings, seen from the near one, are
  // deep and noisy, and would spoil a fit that the near end's sightings make.
  line_ = line;
}

namespace {

// A turn's sightings along the line fitted with s(t) = c0 + c1 t + c2 t^2: how hard it braked,
// |2 c2|, and where it came to rest, the parabola's vertex.
struct Turn {
  double deceleration_m_s2 = 0.0;
  double end_m = 0.0;
};
std::optional<Turn> fit_turn(const std::vector<double>& t, const std::vector<double>& s) {
  constexpr std::size_t kLeast = 8;
  if (t.size() < kLeast) return std::nullopt;
  Eigen::MatrixXd a(static_cast<Eigen::Index>(t.size()), 3);
  Eigen::VectorXd b(static_cast<Eigen::Index>(t.size()));
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double dt = t[i] - t.front();
    a.row(static_cast<Eigen::Index>(i)) << 1.0, dt, dt * dt;
    b(static_cast<Eigen::Index>(i)) = s[i];
  }
  const Eigen::Vector3d c = a.colPivHouseholderQr().solve(b);
  const double rest_s = c(2) != 0.0 ? -c(1) / (2.0 * c(2)) : -1.0;
  if (rest_s < 0.0 || rest_s > t.back() - t.front()) return std::nullopt;  // no turn within the sightings
  return Turn{std::abs(2.0 * c(2)), c(0) + c(1) * rest_s + c(2) * rest_s * rest_s};
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

}  // namespace

std::optional<PatrolLine> LinePatrol::fit_window() const {
  const auto n = static_cast<int>(window_.size());
  if (n < cfg_.min_sightings) return std::nullopt;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Sighting& s : window_) mean += s.position;
  mean /= n;
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const Sighting& s : window_) scatter += (s.position - mean) * (s.position - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(scatter / n);
  const Eigen::Vector3d direction = eigen.eigenvectors().col(2);  // the largest eigenvalue's
  // The residual off the line: the two smaller eigenvalues are the mean squared distance across it.
  const double residual = std::sqrt(std::max(0.0, eigen.eigenvalues()(0) + eigen.eigenvalues()(1)));
  if (residual > cfg_.max_residual_m) return std::nullopt;
  std::vector<double> along(window_.size());
  for (std::size_t i = 0; i < window_.size(); ++i) along[i] = (window_[i].position - mean).dot(direction);
  // Near the ends: the 2nd and 98th percentiles of the sightings along the line (the extremes
  // would be a stray sighting's); where the target turned, the turn says where exactly.
  std::vector<double> sorted = along;
  std::sort(sorted.begin(), sorted.end());
  const auto percentile = [&](double q) { return sorted[static_cast<std::size_t>(q * (n - 1))]; };
  const double lo = percentile(0.02), hi = percentile(0.98);
  if (hi - lo < cfg_.min_length_m) return std::nullopt;
  // A turn at an end: seen without a break longer than max_gap_s, the target came to it from
  // turn_m inside it and went back as far. A target that left the camera's view near a point and
  // came back into it there has not turned there; one that flew on beyond it did not either. The
  // turn's sightings give where it came to rest and how hard it braked.
  std::vector<double> decelerations;
  const auto turns_at = [&](double end, double inward) {
    std::vector<double> ends;
    bool started = false, reached = false;
    std::vector<double> turn_t, turn_s;
    for (std::size_t i = 0; i < along.size(); ++i) {
      if (i > 0 && window_[i].t - window_[i - 1].t > cfg_.max_gap_s) {
        started = reached = false;
        turn_t.clear();
        turn_s.clear();
      }
      const double inside = inward * (along[i] - end);
      if (inside >= cfg_.turn_m) {
        if (started && reached)
          if (const auto turn = fit_turn(turn_t, turn_s)) {
            ends.push_back(turn->end_m);
            decelerations.push_back(turn->deceleration_m_s2);
          }
        started = true;
        reached = false;
        turn_t.clear();
        turn_s.clear();
      } else if (started) {
        reached = reached || inside <= 0.5 * cfg_.turn_m;
        turn_t.push_back(window_[i].t);
        turn_s.push_back(along[i]);
      }
    }
    return ends;
  };
  const std::vector<double> lo_turns = turns_at(lo, 1.0), hi_turns = turns_at(hi, -1.0);
  if (lo_turns.empty() && hi_turns.empty()) return std::nullopt;
  const double lo_end = lo_turns.empty() ? lo : median(lo_turns), hi_end = hi_turns.empty() ? hi : median(hi_turns);
  PatrolLine line;
  line.direction = direction;
  line.centre = mean + 0.5 * (hi_end + lo_end) * direction;
  line.half_length_m = 0.5 * (hi_end - lo_end);
  line.rms_residual_m = residual;
  line.turned = {!lo_turns.empty(), !hi_turns.empty()};
  // The cruise: the 90th percentile of the speeds along the line over spans of kSpan_s.
  constexpr double kSpan_s = 0.2;
  std::vector<double> speeds;
  for (std::size_t i = 0, j = 0; i < along.size(); ++i) {
    while (j < along.size() && window_[j].t - window_[i].t < kSpan_s) ++j;
    if (j == along.size()) break;
    if (window_[j].t - window_[i].t <= kSpan_s + cfg_.max_gap_s)
      speeds.push_back(std::abs(along[j] - along[i]) / (window_[j].t - window_[i].t));
  }
  if (!speeds.empty()) {
    std::sort(speeds.begin(), speeds.end());
    line.cruise_speed_m_s = speeds[static_cast<std::size_t>(0.9 * static_cast<double>(speeds.size() - 1))];
  }
  line.deceleration_m_s2 = median(decelerations);
  return line;
}

Eigen::Vector3d patrol_lookout(const PatrolLine& line, int end_index, double standoff_m) {
  Eigen::Vector3d outward = (end_index == 0 ? -1.0 : 1.0) * line.direction;
  outward.z() = 0.0;
  if (outward.norm() < 1e-6) return line.end(end_index);
  return line.end(end_index) + standoff_m * outward.normalized();
}

}  // namespace kestrel::aim
