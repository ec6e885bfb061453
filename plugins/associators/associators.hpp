#pragma once
// The data associators: optimal (Hungarian) and greedy nearest neighbour, on Euclidean or
// Mahalanobis distance, with a gate beyond which nothing is assigned.
#include "kestrel/component.hpp"
#include "kestrel/node_spec.hpp"
#include "kestrel/tracking/associator.hpp"

namespace kestrel::tracking {

enum class Metric { euclidean, mahalanobis };

struct AssociatorConfig {
  Metric metric = Metric::euclidean;
  double gate_m = 1.0;      ///< euclidean: epsilon_max
  double gate_sigma = 3.0;  ///< mahalanobis: standard deviations

  double gate() const { return metric == Metric::mahalanobis ? gate_sigma : gate_m; }
};

/// Track-to-detection distances; pairs beyond `gate` are marked forbidden.
Eigen::MatrixXd distance_matrix(const std::vector<PredictedMeasurement>& tracks,
                                const std::vector<Eigen::Vector3d>& detections, Metric metric, double gate);

class HungarianAssociator final : public Associator {
 public:
  static ComponentSpec spec();
  explicit HungarianAssociator(const ComponentInit& init);
  explicit HungarianAssociator(const AssociatorConfig& config) : HungarianAssociator(config.metric, config.gate()) {}
  HungarianAssociator(Metric metric, double gate) : metric_(metric), gate_(gate) {}
  algorithms::Assignment associate(const std::vector<PredictedMeasurement>& tracks,
                                   const std::vector<Eigen::Vector3d>& detections) const override;

 private:
  Metric metric_;
  double gate_;
};

/// Pairs the closest remaining track and detection, again and again. Not optimal: a pair it takes
/// early can leave another track without the only detection within its gate.
class GreedyAssociator final : public Associator {
 public:
  static ComponentSpec spec();
  explicit GreedyAssociator(const ComponentInit& init);
  explicit GreedyAssociator(const AssociatorConfig& config) : GreedyAssociator(config.metric, config.gate()) {}
  GreedyAssociator(Metric metric, double gate) : metric_(metric), gate_(gate) {}
  algorithms::Assignment associate(const std::vector<PredictedMeasurement>& tracks,
                                   const std::vector<Eigen::Vector3d>& detections) const override;

 private:
  Metric metric_;
  double gate_;
};

}  // namespace kestrel::tracking
