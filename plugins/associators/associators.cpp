#include "associators.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <tuple>

namespace kestrel::tracking {

namespace {

// The parameters both associators take.
ConfigSpec<AssociatorConfig> associator_config() {
  ConfigSpec<AssociatorConfig> c;
  c.choice("metric", &AssociatorConfig::metric,
           {{"euclidean", Metric::euclidean}, {"mahalanobis", Metric::mahalanobis}})
      .describe("distance between a track's predicted position and a detection");
  c.param("gate_m", &AssociatorConfig::gate_m)
      .range(0.0, 1000.0)
      .with_unit("m")
      .describe("euclidean: epsilon_max, never assign farther (paper: 1.0 m, its largest reconstruction error)");
  c.param("gate_sigma", &AssociatorConfig::gate_sigma)
      .range(0.0, 1000.0)
      .with_unit("sigma")
      .describe("mahalanobis: never assign beyond this many standard deviations");
  return c;
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
  return ComponentSpec("hungarian", "Optimal assignment (Hungarian method) within a gate")
      .details(
          "Among the assignments with the most pairs within the gate, one of least total track-to-detection "
          "distance (rectangular linear sum assignment, paper section 2.3.1).")
      .config(associator_config());
}

HungarianAssociator::HungarianAssociator(const ComponentInit& init)
    : HungarianAssociator(init.config<AssociatorConfig>()) {}

algorithms::Assignment HungarianAssociator::associate(const std::vector<PredictedMeasurement>& tracks,
                                                      const std::vector<Eigen::Vector3d>& detections) const {
  return algorithms::solve_assignment(distance_matrix(tracks, detections, metric_, gate_), gate_);
}

ComponentSpec GreedyAssociator::spec() {
  return ComponentSpec("greedy", "Greedy nearest neighbour within a gate")
      .details(
          "Repeatedly pairs the closest remaining track and detection; fast, and the baseline to A/B against the "
          "Hungarian associator. Not optimal: an early closest pair can take the only detection within another "
          "track's gate.")
      .config(associator_config());
}

GreedyAssociator::GreedyAssociator(const ComponentInit& init) : GreedyAssociator(init.config<AssociatorConfig>()) {}

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
