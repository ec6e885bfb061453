#pragma once
// A track filter whose estimate is the last detection, with a covariance the test chooses: the
// tracking loop and the selectors tested without a filter's dynamics.
#include <Eigen/Core>

#include "kestrel/tracking/filter.hpp"

namespace kestrel::testing {

class FixedFilter final : public tracking::TrackFilter {
 public:
  explicit FixedFilter(const Eigen::Vector3d& z, double variance = 1.0) : p_(z), variance_(variance) {}
  void predict(double) override {}
  void update(const Eigen::Vector3d& z) override { p_ = z; }
  tracking::PredictedMeasurement predicted_measurement() const override { return {p_, Eigen::Matrix3d::Identity()}; }
  Eigen::VectorXd state() const override { return p_; }
  Eigen::MatrixXd covariance() const override { return variance_ * Eigen::Matrix3d::Identity(); }

 private:
  Eigen::Vector3d p_;
  double variance_;
};

}  // namespace kestrel::testing
