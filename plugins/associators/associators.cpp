#include "associators.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <tuple>

namespace kestrel::tracking {

namespace {

Metric parse_metric(const Params& p) {
  return p.get<std::string>("metric") == "mahalanobis" ? Metric::mahalanobis : Metric::euclidean;
}

double gate_of(const Params& p) {
  return parse_metric(p) == Metric::mahalanobis ? p.get<double>("gate_sigma") : p.get<double>("gate_m");
}

ComponentSpec with_common_params(ComponentSpec spec) {
  return spec
      .param(param("metric", std::string("euclidean"))
                 .one_of({"euclidean", "mahalanobis"})
                 .describe("distance between a track's predicted position and a detection"))
      .param(param("gate_m", 1.0)
                 .range(0.0, 1000.0)
                 .with_unit("m")
                 .describe(
                     "euclidean: epsilon_max, never assign farther (paper: 1.0 m, its largest reconstruction error)"))
      .param(param("gate_sigma", 3.0)
                 .range(0.0, 1000.0)
                 .with_unit("sigma")
                 .describe("mahalanobis: never assign beyond this many standard deviations"));
}

}  // namespace

Eigen::MatrixXd distance_matrix(const std::vector<PredictedMeasurement>& tracks,
                                const std::vector<Eigen::Vector3d>& detections, Metric metric, double gate) {
  Eigen::MatrixXd cost(static_cast<Eigen::Index>(tracks.size()), static_cast<Eigen::Index>(detections.size()));
  for (std::size_t t = 0; t < tracks.size(); ++t) {
    const Eigen::LLT<Eigen::Matrix3d> llt(tracks[t].innovation_covariance);
    for (std::size_t d = 0; d < detections.size(); ++d) {
      const Eigen::Vector3d e = detections[d] - tracks[t].position;
      const double distance = metric == Metric::euclidean ? e.norm() : std::sqrt(e.dot(llt.solve(e)));
      cost(static_cast<Eigen::Index>(t), static_cast<Eigen::Index>(d)) =
          distance <= gate ? distance : algorithms::kForbidden;
    }
  }
  return cost;
}

ComponentSpec HungarianAssociator::spec() {
  return with_common_params(ComponentSpec("hungarian", "Optimal assignment (Hungarian method) within a gate"))
      .details(
          "Minimises the sum of track-to-detection distances over all tracks and detections (rectangular "
          "linear sum assignment, paper section 2.3.1); a pair beyond the gate is never assigned.");
}

HungarianAssociator::HungarianAssociator(const Params& p) : metric_(parse_metric(p)), gate_(gate_of(p)) {}

algorithms::Assignment HungarianAssociator::associate(const std::vector<PredictedMeasurement>& tracks,
                                                      const std::vector<Eigen::Vector3d>& detections) const {
  return algorithms::solve_assignment(distance_matrix(tracks, detections, metric_, gate_), gate_);
}

ComponentSpec GreedyAssociator::spec() {
  return with_common_params(ComponentSpec("greedy", "Greedy nearest neighbour within a gate"))
      .details(
          "Repeatedly pairs the closest remaining track and detection; fast, and the baseline to A/B "
          "against the Hungarian associator.");
}

GreedyAssociator::GreedyAssociator(const Params& p) : metric_(parse_metric(p)), gate_(gate_of(p)) {}

algorithms::Assignment GreedyAssociator::associate(const std::vector<PredictedMeasurement>& tracks,
                                                   const std::vector<Eigen::Vector3d>& detections) const {
  const Eigen::MatrixXd cost = distance_matrix(tracks, detections, metric_, gate_);
  std::vector<std::tuple<double, int, int>> pairs;
  for (int t = 0; t < cost.rows(); ++t)
    for (int d = 0; d < cost.cols(); ++d)
      if (std::isfinite(cost(t, d))) pairs.emplace_back(cost(t, d), t, d);
  std::sort(pairs.begin(), pairs.end());  // by distance, then track, then detection: deterministic
  algorithms::Assignment a;
  a.row_to_col.assign(tracks.size(), -1);
  a.col_to_row.assign(detections.size(), -1);
  for (const auto& [c, t, d] : pairs) {
    if (a.row_to_col[static_cast<std::size_t>(t)] >= 0 || a.col_to_row[static_cast<std::size_t>(d)] >= 0) continue;
    a.row_to_col[static_cast<std::size_t>(t)] = d;
    a.col_to_row[static_cast<std::size_t>(d)] = t;
    a.total_cost += c;
    ++a.pairs;
  }
  return a;
}

}  // namespace kestrel::tracking
