#pragma once
// The data-association component interface: which detection updates which track. Trackers load
// an associator by name from their parameters (`associator: hungarian` or `greedy`); plugins
// provide the implementations as components of kind "associator".
#include <Eigen/Core>
#include <string_view>
#include <vector>

#include "kestrel/algorithms/assignment.hpp"

namespace kestrel::tracking {

/// A track's predicted measurement: where the tracker expects its detection, and the innovation
/// covariance S = H P H^T + R of that expectation (for Mahalanobis distances).
struct PredictedMeasurement {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Matrix3d innovation_covariance = Eigen::Matrix3d::Identity();
};

class Associator {
 public:
  static constexpr std::string_view kKind = "associator";
  virtual ~Associator() = default;

  /// Rows are tracks, columns detections. A pair beyond the associator's gate is never assigned.
  virtual algorithms::Assignment associate(const std::vector<PredictedMeasurement>& tracks,
                                           const std::vector<Eigen::Vector3d>& detections) const = 0;
};

}  // namespace kestrel::tracking
