#include "kestrel/guidance/futures_calibration.hpp"

#include <fmt/format.h>

#include <Eigen/Cholesky>
#include <cmath>

#include "kestrel/guidance/target_futures.hpp"

namespace kestrel::guidance {

namespace {
constexpr double kMatch_s = 0.02;  // a drawing this near t - tau foresaw the sighting at t
}

FuturesCalibration::FuturesCalibration(std::vector<double> taus) : taus_(std::move(taus)) {
  for (double tau : taus_) tallies_.push_back(Tally{tau});
}

void FuturesCalibration::add(double t, const TargetFutures& futures) {
  if (futures.empty()) return;
  Drawn d;
  d.t = t;
  for (double tau : taus_) {
    std::vector<Eigen::Vector3d> at;
    if (tau <= futures.horizon_s() + 1e-9)
      for (std::size_t i = 0; i < futures.size(); ++i) at.push_back(futures.position(i, tau));
    d.at.push_back(std::move(at));
  }
  drawn_.push_back(std::move(d));
  double longest = 0.0;
  for (double tau : taus_) longest = std::max(longest, tau);
  while (!drawn_.empty() && drawn_.front().t < t - longest - 1.0) drawn_.pop_front();
}

void FuturesCalibration::observe(double t, const Eigen::Vector3d& seen) {
  for (std::size_t k = 0; k < taus_.size(); ++k) {
    const Drawn* best = nullptr;
    for (const Drawn& d : drawn_)
      if (std::abs(d.t + taus_[k] - t) <= kMatch_s &&
          (!best || std::abs(d.t + taus_[k] - t) < std::abs(best->t + taus_[k] - t)))
        best = &d;
    if (!best || best->at[k].size() < 4) continue;
    const double r = rank(best->at[k], seen);
    Tally& tally = tallies_[k];
    ++tally.sightings;
    tally.within_half += r <= 0.5;
    tally.within_90 += r <= 0.9;
    tally.rank_sum += r;
  }
}

double FuturesCalibration::rank(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& seen) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const auto& p : points) covariance += (p - mean) * (p - mean).transpose();
  covariance /= static_cast<double>(points.size());
  // A floor on the spread: paths that agree to the millimetre still leave the sighting its noise.
  covariance += 1e-4 * Eigen::Matrix3d::Identity();
  const Eigen::LDLT<Eigen::Matrix3d> ldlt(covariance);
  const auto distance = [&](const Eigen::Vector3d& p) { return (p - mean).dot(ldlt.solve(p - mean)); };
  const double d = distance(seen);
  std::size_t nearer = 0;
  for (const auto& p : points) nearer += distance(p) < d;
  return static_cast<double>(nearer) / static_cast<double>(points.size());
}

nlohmann::json FuturesCalibration::report() const {
  nlohmann::json out = nlohmann::json::object();
  for (const Tally& t : tallies_)
    out[fmt::format("{:g}", t.tau_s)] = {
        {"sightings", t.sightings},
        {"within_half", t.within_half},
        {"within_90", t.within_90},
        {"mean_rank", t.sightings ? nlohmann::json(t.rank_sum / static_cast<double>(t.sightings)) : nlohmann::json()}};
  return out;
}

}  // namespace kestrel::guidance
