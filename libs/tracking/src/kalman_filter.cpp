#include "kestrel/tracking/kalman_filter.hpp"

namespace kestrel::tracking {

KalmanTrack::KalmanTrack(const Eigen::Vector3d& first_detection, const KalmanConfig& config)
    : kf_(ConstantAccelerationKalman::start(first_detection, config.p)), cfg_(config) {}

void KalmanTrack::predict(double dt) { kf_.predict(dt, cfg_.q); }

void KalmanTrack::update(const Eigen::Vector3d& z) { kf_.update(z, cfg_.r); }

PredictedMeasurement KalmanTrack::predicted_measurement() const {
  return {kf_.position(), kf_.innovation_covariance(cfg_.r)};
}

ComponentSpec KalmanFilter::spec() {
  ConfigSpec<KalmanConfig> c;
  declare(c);
  return ComponentSpec("kalman", "Constant-acceleration Kalman filter per track (paper, 2.3)")
      .details(
          "Each track is a 9-state constant-acceleration Kalman filter (position, velocity, acceleration) measured "
          "by detection centroids. Q is the discrete white-noise-jerk model scaled by q, R = r I3, "
          "P0 = p diag(1^2, 30^2, 5.5^2) per axis; Joseph-form update.")
      .config(std::move(c));
}

KalmanFilter::KalmanFilter(const ComponentInit& init) : cfg_(init.config<KalmanConfig>()) {}

std::unique_ptr<TrackFilter> KalmanFilter::start(const Eigen::Vector3d& first_detection) {
  return std::make_unique<KalmanTrack>(first_detection, cfg_);
}

}  // namespace kestrel::tracking
