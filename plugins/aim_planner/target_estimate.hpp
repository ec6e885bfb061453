#pragma once
// The aim's estimate of its target in the world frame, from what was seen of it there: a
// constant-acceleration Kalman filter (`ca`, the paper's model) or an IMM of a steady and a
// manoeuvring one (`imm`, kestrel/tracking/imm_filter.hpp), and how uncertain its prediction
// grows over the time a net flies.
#include <Eigen/Core>
#include <kestrel/tracking/imm_filter.hpp>
#include <kestrel/tracking/kalman_filter.hpp>
#include <variant>

namespace kestrel::aim {

struct TargetFilterConfig {
  enum class Model { constant_acceleration, imm };
  Model model = Model::constant_acceleration;
  double q = 1.0;               ///< m^2/s^5: the jerk intensity (imm: of its steady model)
  double q_manoeuvre = 1000.0;  ///< m^2/s^5: imm: of its manoeuvre model
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

 private:
  std::variant<tracking::KalmanTrack, tracking::ImmTrack> filter_;
};

}  // namespace kestrel::aim
