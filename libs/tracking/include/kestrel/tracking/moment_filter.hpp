#pragma once
// A filter whose estimate is the mean and covariance of a distribution it holds (weighted
// particles, a mixture of motion models): the published state, its covariance and the predicted
// measurement all come from those two moments, computed here once for every such filter.
#include "kestrel/tracking/constant_acceleration.hpp"
#include "kestrel/tracking/filter.hpp"

namespace kestrel::tracking {

class MomentTrackFilter : public TrackFilter {
 public:
  PredictedMeasurement predicted_measurement() const override {
    State mean;
    Covariance cov;
    moments(mean, cov);
    return {mean.head<3>(), cov.topLeftCorner<3, 3>() + measurement_noise() * Eigen::Matrix3d::Identity()};
  }
  Eigen::VectorXd state() const override {
    State mean;
    Covariance cov;
    moments(mean, cov);
    return mean;
  }
  Eigen::MatrixXd covariance() const override {
    State mean;
    Covariance cov;
    moments(mean, cov);
    return cov;
  }

 protected:
  /// The distribution's mean and covariance.
  virtual void moments(State& mean, Covariance& cov) const = 0;
  /// r of R = r I3, m^2.
  virtual double measurement_noise() const = 0;
};

}  // namespace kestrel::tracking
