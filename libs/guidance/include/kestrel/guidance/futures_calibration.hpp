#pragma once
// How well the target's futures foresaw it: each sighting is ranked among the paths drawn `tau`
// seconds before it. The rank is the share of the paths nearer their own mean (in the Mahalanobis
// distance of their spread) than the sighting: for futures that are neither too narrow nor too wide
// it is uniform on [0, 1], so half the sightings fall within the paths' central half and nine in ten
// within their central 90 %. Too many outside: the manoeuvre noise is too small; too few: too large.
// The aim reports it per run, and the capture benchmark sums it over the engagements, so that the
// predictor's noise is chosen on the tracks, not on capture counts.
#include <Eigen/Core>
#include <deque>
#include <nlohmann/json.hpp>
#include <vector>

namespace kestrel::guidance {

struct TargetFutures;

class FuturesCalibration {
 public:
  /// The look-aheads ranked, s.
  explicit FuturesCalibration(std::vector<double> taus = {0.5, 1.0, 2.0});
  /// The futures drawn at time t (their origin).
  void add(double t, const TargetFutures& futures);
  /// A sighting at time t (world): ranked among the futures drawn about tau before it.
  void observe(double t, const Eigen::Vector3d& seen);
  /// A new target: the futures drawn for the last foresee nothing of it.
  void forget() { drawn_.clear(); }

  struct Tally {
    double tau_s = 0.0;
    std::uint64_t sightings = 0, within_half = 0, within_90 = 0;
    double rank_sum = 0.0;
  };
  const std::vector<Tally>& tallies() const { return tallies_; }
  /// {"TAU": {sightings, within_half, within_90, mean_rank}} (the counts sum over runs).
  nlohmann::json report() const;

  /// The rank of `seen` among `points`: the share nearer their mean, in their spread's metric.
  static double rank(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& seen);

 private:
  struct Drawn {
    double t = 0.0;
    std::vector<std::vector<Eigen::Vector3d>> at;  // per tau, each path's position
  };
  std::vector<double> taus_;
  std::vector<Tally> tallies_;
  std::deque<Drawn> drawn_;
};

}  // namespace kestrel::guidance
