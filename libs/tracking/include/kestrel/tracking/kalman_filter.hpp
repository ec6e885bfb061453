#pragma once
// The `kalman` filter component: each track is the paper's 3D constant-acceleration Kalman filter
// (kestrel/tracking/constant_acceleration.hpp) with process noise q, measurement noise r and
// initial covariance scale p.
#include <memory>

#include "kestrel/component.hpp"
#include "kestrel/config_spec.hpp"
#include "kestrel/node_spec.hpp"
#include "kestrel/tracking/constant_acceleration.hpp"
#include "kestrel/tracking/filter.hpp"

namespace kestrel::tracking {

struct KalmanConfig {
  double q = 1.0;  ///< white-noise-jerk intensity, m^2/s^5
  double r = 1.0;  ///< measurement noise: R = r I3, m^2
  double p = 1.0;  ///< P0 = p diag(1, 900, 30.25) per axis
};

/// One track's constant-acceleration Kalman filter.
class KalmanTrack final : public TrackFilter {
 public:
  KalmanTrack(const Eigen::Vector3d& first_detection, const KalmanConfig& config);
  void predict(double dt) override;
  void update(const Eigen::Vector3d& z) override;
  PredictedMeasurement predicted_measurement() const override;
  Eigen::VectorXd state() const override { return kf_.x; }
  Eigen::MatrixXd covariance() const override { return kf_.P; }

 private:
  ConstantAccelerationKalman kf_;
  KalmanConfig cfg_;
};

class KalmanFilter final : public Filter {
 public:
  static ComponentSpec spec();
  /// Declares q, r and p.
  static void declare(ConfigSpec<KalmanConfig>& c) {
    c.param("q", &KalmanConfig::q).range(0.0, 1e6).with_unit("m^2/s^5").describe("process noise (jerk) intensity");
    c.param("r", &KalmanConfig::r)
        .range(1e-9, 1e6)
        .with_unit("m^2")
        .describe("measurement noise: R = r I3 (paper: best RMSE at r = 1.0)");
    c.param("p", &KalmanConfig::p)
        .range(1e-9, 1e6)
        .describe("initial covariance scale: P0 = p diag(1, 900, 30.25) per axis");
  }

  explicit KalmanFilter(const ComponentInit& init);
  explicit KalmanFilter(KalmanConfig config) : cfg_(config) {}

  std::unique_ptr<TrackFilter> start(const Eigen::Vector3d& first_detection) override;

 private:
  KalmanConfig cfg_;
};

}  // namespace kestrel::tracking
