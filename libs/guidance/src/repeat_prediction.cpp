#include "kestrel/guidance/repeat_prediction.hpp"

#include <algorithm>
#include <cmath>

namespace kestrel::guidance {

namespace {
constexpr double kForecastMatch_s = 0.02;  // a forecast this near now - check_s is checked now
constexpr double kSeparation_s = 0.5;      // two analogues from one pass are one analogue

}  // namespace

RepeatPredictor::RepeatPredictor(RepeatConfig config) : cfg_(config) {}

double RepeatPredictor::probability() const { return weight_.probability(); }

void RepeatPredictor::observe(double dt, const Eigen::Vector3d& position, const Eigen::Vector3d& velocity) {
  if (!weight_.active()) return;
  now_ += std::max(dt, 0.0);
  past_.push_back({now_, position, velocity});
  while (!past_.empty() && past_.front().t < now_ - cfg_.window_s) past_.pop_front();
  // The forecasts made check_s ago, against where the target is now.
  for (const Forecast& f : forecasts_)
    if (f.repeat && std::abs(f.t + cfg_.check_s - now_) <= kForecastMatch_s) {
      const double scale = 2.0 * cfg_.error_m * cfg_.error_m;
      const double ratio = ((position - f.models).squaredNorm() - (position - *f.repeat).squaredNorm()) / scale;
      weight_.add(std::min(dt, 0.1) / cfg_.evidence_time_s * std::clamp(ratio, -4.0, 4.0));
    }
  while (!forecasts_.empty() && forecasts_.front().t < now_ - cfg_.check_s - 0.1) forecasts_.pop_front();
}

Eigen::Vector3d RepeatPredictor::position_at(double t) const {
  const auto after = std::lower_bound(past_.begin(), past_.end(), t, [](const Past& p, double x) { return p.t < x; });
  if (after == past_.begin()) return past_.front().position;
  if (after == past_.end()) return past_.back().position;
  const Past& b = *after;
  const Past& a = *std::prev(after);
  const double w = b.t > a.t ? (t - a.t) / (b.t - a.t) : 0.0;
  return (1.0 - w) * a.position + w * b.position;
}

std::vector<Eigen::Matrix3Xd> RepeatPredictor::paths(Eigen::Index steps, double step_s,
                                                     const Eigen::Vector3d& models_ahead) {
  std::vector<Eigen::Matrix3Xd> out;
  if (!weight_.active() || past_.empty()) return out;
  const Past& present = past_.back();
  const double horizon = static_cast<double>(steps) * step_s;
  // The past states whose next horizon is known, by how near they are to the present one.
  std::vector<std::pair<double, std::size_t>> near;
  for (std::size_t j = 0; j < past_.size() && past_[j].t + horizon <= now_; ++j) {
    const double d = std::hypot((past_[j].position - present.position).norm() / cfg_.position_m,
                                (past_[j].velocity - present.velocity).norm() / cfg_.velocity_m_s);
    if (d <= cfg_.max_distance) near.emplace_back(d, j);
  }
  std::sort(near.begin(), near.end());
  std::vector<double> chosen;
  for (const auto& [d, j] : near) {
    if (static_cast<std::int64_t>(chosen.size()) >= cfg_.matches) break;
    const double t = past_[j].t;
    if (std::any_of(chosen.begin(), chosen.end(), [t](double c) { return std::abs(c - t) < kSeparation_s; })) continue;
    chosen.push_back(t);
    Eigen::Matrix3Xd path(3, steps + 1);
    for (Eigen::Index k = 0; k <= steps; ++k)
      path.col(k) = present.position + position_at(t + static_cast<double>(k) * step_s) - past_[j].position;
    out.push_back(std::move(path));
  }
  Forecast f{now_, std::nullopt, models_ahead};
  if (!out.empty()) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (const auto& path : out) {
      const double k = std::clamp(cfg_.check_s / step_s, 0.0, static_cast<double>(steps));
      const auto lo = static_cast<Eigen::Index>(std::floor(k));
      const Eigen::Index hi = std::min<Eigen::Index>(lo + 1, steps);
      sum += (1.0 - (k - static_cast<double>(lo))) * path.col(lo) + (k - static_cast<double>(lo)) * path.col(hi);
    }
    f.repeat = sum / static_cast<double>(out.size());
  }
  forecasts_.push_back(f);
  return out;
}

}  // namespace kestrel::guidance
