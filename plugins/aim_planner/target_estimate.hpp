#pragma once
// The aim's estimate of its target in the world frame, from what was seen of it there: a
// constant-acceleration Kalman filter (`ca`, the paper's model), a constant-velocity one (`cv`),
// or an IMM of constant velocity, constant acceleration and a coordinated turn (`imm`,
// kestrel/tracking/imm_filter.hpp), and how uncertain its prediction grows over the time a net
// flies.
#include <Eigen/Core>
#include <kestrel/guidance/target_futures.hpp>
#include <kestrel/tracking/imm_filter.hpp>
#include <kestrel/tracking/kalman_filter.hpp>
#include <variant>
#include <vector>

namespace kestrel::aim {

struct TargetFilterConfig {
  enum class Model { constant_velocity, constant_acceleration, imm };
  Model model = Model::constant_acceleration;
  double q = 1.0;           ///< m^2/s^5: the constant-acceleration model's jerk intensity
  double q_velocity = 1.0;  ///< m^2/s^3: the constant-velocity model's acceleration intensity
  double q_turn = 10.0;     ///< m^2/s^5: imm: the coordinated turn's jerk intensity
  double switch_probability = 0.01;
  double r = 1.0;  ///< m^2: the detections' variance
};

class TargetEstimate {
 public:
  TargetEstimate(const Eigen::Vector3d& first_sighting, const TargetFilterConfig& config);
  void predict(double dt);
  void update(const Eigen::Vector3d& sighting);
  /// [x y z vx vy vz ax ay az], world frame.
  Eigen::VectorXd state() const;
  Eigen::MatrixXd covariance() const;
  /// The position's covariance predicted `tau` seconds ahead (this estimate is left as it is).
  Eigen::Matrix3d position_covariance_after(double tau) const;
  /// The position predicted `tau` seconds ahead by the estimate's own model (imm: each model's
  /// prediction weighted by its probability now).
  Eigen::Vector3d position_after(double tau) const;
  /// The imm's model probabilities (cv, ca, ct); empty for a single model.
  std::vector<double> model_probabilities() const;
  /// Each model's state, covariance and probability, for the predictor of the target's futures.
  std::vector<guidance::MotionHypothesis> hypotheses() const;

 private:
  std::variant<tracking::KalmanTrack, tracking::ImmTrack> filter_;
};

}  // namespace kestrel::aim
