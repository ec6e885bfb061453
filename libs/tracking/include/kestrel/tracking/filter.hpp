#pragma once
// The per-track estimator as a component of kind "filter": a Filter makes the estimator of each
// new track from its first detection, and the tracker drives it (predict to the frame's time,
// then update with the associated detection, if any).
//
// Implementations: `kalman` (the paper's constant-acceleration Kalman filter,
// kestrel/tracking/kalman_filter.hpp) and `particle` (the same model as MRPT particle filters,
// plugins/particle_tracker). The interface asks only for what the tracker and the associators
// use, so that an IMM (several motion models mixed by their likelihoods) or a UKF fits as it is:
// predict and update its models, give the mixed position and innovation covariance to the
// associator, and publish the mixed state (see docs/tracking.md, "Writing a filter").
#include <Eigen/Core>
#include <memory>
#include <string_view>

#include "kestrel/tracking/associator.hpp"

namespace kestrel::tracking {

/// One track's estimator. The tracker calls predict() once a frame (not for the track's birth
/// frame, and never with dt <= 0), then update() if a detection was associated.
class TrackFilter {
 public:
  virtual ~TrackFilter() = default;
  virtual void predict(double dt) = 0;
  virtual void update(const Eigen::Vector3d& z) = 0;
  /// Where the next detection is expected, and the innovation covariance S of that expectation
  /// (the associators' input; a Mahalanobis gate uses S).
  virtual PredictedMeasurement predicted_measurement() const = 0;
  /// The published estimate. Its first three elements are the position [x y z] in the
  /// detections' frame (msg::Track::position() reads them); for the constant-acceleration
  /// filters it is [x y z vx vy vz ax ay az].
  virtual Eigen::VectorXd state() const = 0;
  /// The covariance of state(); its top-left 3x3 block is the position's.
  virtual Eigen::MatrixXd covariance() const = 0;
};

/// The `filter` component: makes the estimator of each new track. Not const: a filter may hold
/// a random stream that each new track draws its own seed from.
class Filter {
 public:
  static constexpr std::string_view kKind = "filter";
  virtual ~Filter() = default;
  virtual std::unique_ptr<TrackFilter> start(const Eigen::Vector3d& first_detection) = 0;
};

}  // namespace kestrel::tracking
