#pragma once
// The `imm` filter component: an interacting multiple model (IMM) filter per track (Blom and
// Bar-Shalom). Kalman filters of several motion models (kestrel/tracking/motion_models.hpp) run
// side by side on the same state; each frame they are mixed by how likely each has been, with a
// Markov chain for switching between them. The tracker's component runs two of the paper's
// constant-acceleration filters, one with little process noise (steady flight: smooth, low-noise
// estimates) and one with much (manoeuvres: a quick response to a turn or a braking), and on
// request a constant-velocity and a coordinated-turn model beside them. A drone that flies
// steadily and then jinks gets the first filter's smoothness and the second's agility, which
// one fixed q cannot give.
#include <memory>
#include <vector>

#include "kestrel/component.hpp"
#include "kestrel/config_spec.hpp"
#include "kestrel/node_spec.hpp"
#include "kestrel/tracking/constant_acceleration.hpp"
#include "kestrel/tracking/moment_filter.hpp"
#include "kestrel/tracking/motion_models.hpp"

namespace kestrel::tracking {

struct ImmConfig {
  double q_steady = 1.0;             ///< jerk intensity of the steady model, m^2/s^5
  double q_manoeuvre = 1000.0;       ///< jerk intensity of the manoeuvre model, m^2/s^5
  double switch_probability = 0.01;  ///< chance a frame that the motion changes model
  double r = 1.0;                    ///< measurement noise: R = r I3, m^2
  double p = 1.0;                    ///< P0 = p diag(1, 900, 30.25) per axis
  double q_velocity = 0.0;  ///< > 0: a constant-velocity model joins, with this acceleration intensity, m^2/s^3
  double q_turn = 0.0;      ///< > 0: a coordinated-turn model joins, with this jerk intensity, m^2/s^5
};

/// One model of an IMM: its motion and its process noise intensity (units: motion_models.hpp).
struct ImmModel {
  MotionModel motion = MotionModel::constant_acceleration;
  double q = 1.0;
};

/// The models an ImmConfig declares: steady and manoeuvring constant acceleration, then the
/// constant velocity and the coordinated turn when asked for.
std::vector<ImmModel> imm_models(const ImmConfig& config);

/// One track's IMM filter over its models.
class ImmTrack final : public MomentTrackFilter {
 public:
  /// The first model is where the motion most likely starts (1 - switch_probability); the
  /// chain leaves each model with switch_probability a frame, to the others alike.
  ImmTrack(const Eigen::Vector3d& first_detection, std::vector<ImmModel> models, double switch_probability, double r,
           double p);
  ImmTrack(const Eigen::Vector3d& first_detection, const ImmConfig& config)
      : ImmTrack(first_detection, imm_models(config), config.switch_probability, config.r, config.p) {}
  void predict(double dt) override;
  void update(const Eigen::Vector3d& z) override;
  /// Probability of each model, in the order of models(); they sum to 1.
  const std::vector<double>& model_probabilities() const { return mu_; }
  const std::vector<ImmModel>& models() const { return models_; }
  /// Each model's own filter (its state and covariance), in the order of models().
  const std::vector<ConstantAccelerationKalman>& model_filters() const { return filters_; }
  /// The state predicted tau seconds ahead without changing the filter: each model's own
  /// prediction, weighted by its probability now (no further switching).
  State predicted_state(double tau) const;

 protected:
  // The models' mixture as one Gaussian: its mean and covariance (spread of the means included).
  void moments(State& x, Covariance& P) const override;
  double measurement_noise() const override { return r_; }

 private:
  // The chance the motion passes from model i to model j in a frame.
  double switch_to(std::size_t i, std::size_t j) const;

  std::vector<ImmModel> models_;
  std::vector<ConstantAccelerationKalman> filters_;  // one per model, same state
  std::vector<double> mu_;
  double switch_probability_, r_;
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
