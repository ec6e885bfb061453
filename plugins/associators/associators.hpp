#pragma once
// The data associators: optimal (Hungarian) and greedy nearest neighbour, on Euclidean or
// Mahalanobis distance, with a gate beyond which nothing is assigned.
#include <string>

#include "kestrel/node_spec.hpp"
#include "kestrel/params.hpp"
#include "kestrel/tracking/associator.hpp"

namespace kestrel::tracking {

enum class Metric { euclidean, mahalanobis };

/// Track-to-detection distances; pairs beyond `gate` are marked forbidden.
Eigen::MatrixXd distance_matrix(const std::vector<PredictedMeasurement>& tracks,
                                const std::vector<Eigen::Vector3d>& detections, Metric metric, double gate);

class HungarianAssociator final : public Associator {
 public:
  static ComponentSpec spec();
  explicit HungarianAssociator(const Params& params);
  HungarianAssociator(Metric metric, double gate) : metric_(metric), gate_(gate) {}
  algorithms::Assignment associate(const std::vector<PredictedMeasurement>& tracks,
                                   const std::vector<Eigen::Vector3d>& detections) const override;

 private:
  Metric metric_;
  double gate_;
};

class GreedyAssociator final : public Associator {
 public:
  static ComponentSpec spec();
  explicit GreedyAssociator(const Params& params);
  GreedyAssociator(Metric metric, double gate) : metric_(metric), gate_(gate) {}
  algorithms::Assignment associate(const std::vector<PredictedMeasurement>& tracks,
                                   const std::vector<Eigen::Vector3d>& detections) const override;

 private:
  Metric metric_;
  double gate_;
};

}  // namespace kestrel::tracking
