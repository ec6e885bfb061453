#pragma once
// The `imm` filter component: an interacting multiple model (IMM) filter per track (Blom and
// Bar-Shalom). Two constant-acceleration Kalman filters of the paper's model run side by side,
// one with little process noise (steady flight: smooth, low-noise estimates) and one with much
// (manoeuvres: a quick response to a turn or a braking); each frame they are mixed by how
// likely each has been, with a Markov chain for switching between them. A drone that flies
// steadily and then jinks gets the first filter's smoothness and the second's agility, which
// one fixed q cannot give.
#include <array>
#include <memory>

#include "kestrel/component.hpp"
#include "kestrel/config_spec.hpp"
#include "kestrel/node_spec.hpp"
#include "kestrel/tracking/constant_acceleration.hpp"
#include "kestrel/tracking/moment_filter.hpp"

namespace kestrel::tracking {

struct ImmConfig {
  double q_steady = 1.0;             ///< jerk intensity of the steady model, m^2/s^5
  double q_manoeuvre = 1000.0;       ///< jerk intensity of the manoeuvre model, m^2/s^5
  double switch_probability = 0.01;  ///< chance a frame that the motion changes model
  double r = 1.0;                    ///< measurement noise: R = r I3, m^2
  double p = 1.0;                    ///< P0 = p diag(1, 900, 30.25) per axis
};

/// One track's IMM filter over the two models.
class ImmTrack final : public MomentTrackFilter {
 public:
  static constexpr int kModels = 2;
  ImmTrack(const Eigen::Vector3d& first_detection, const ImmConfig& config);
  void predict(double dt) override;
  void update(const Eigen::Vector3d& z) override;
  /// Probability of each model (steady, manoeuvre); they sum to 1.
  const std::array<double, kModels>& model_probabilities() const { return mu_; }

 protected:
  // The models' mixture as one Gaussian: its mean and covariance (spread of the means included).
  void moments(State& x, Covariance& P) const override;
  double measurement_noise() const override { return cfg_.r; }

 private:
  std::array<ConstantAccelerationKalman, kModels> models_;
  std::array<double, kModels> mu_{0.5, 0.5};
  ImmConfig cfg_;
};

class ImmFilter final : public Filter {
 public:
  static ComponentSpec spec();
  explicit ImmFilter(const ComponentInit& init);
  explicit ImmFilter(ImmConfig config) : cfg_(config) {}
  std::unique_ptr<TrackFilter> start(const Eigen::Vector3d& first_detection) override;

 private:
  ImmConfig cfg_;
};

}  // namespace kestrel::tracking
