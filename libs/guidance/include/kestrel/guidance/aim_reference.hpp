#pragma once
// The setpoint the controller follows: a point that moves at a wanted velocity within the
// hunter's speed and acceleration limits, and turns within its yaw-rate limit. Guidance chooses
// the velocity; the reference never jumps, so neither does the controller.
#include <Eigen/Core>
#include <cmath>

#include "kestrel/guidance/aim_pose.hpp"

namespace kestrel::guidance {

class AimReference {
 public:
  struct Limits {
    double gain = 1.0;              ///< 1/s: pull towards the goal in advance()
    double max_speed = 3.0;         ///< m/s
    double max_acceleration = 3.0;  ///< m/s^2
    double max_yaw_rate = 1.0;      ///< rad/s
    /// rad: the thrust that flies the acceleration (it plus gravity) tilts no further from
    /// vertical; the horizontal part gives way. pi/2: no limit beyond max_acceleration.
    double max_tilt = M_PI / 2.0;
  };

  AimReference(Limits limits, const Eigen::Vector3d& start, double start_yaw);

  /// Moves the reference dt seconds towards `goal` (moving at `goal_velocity`): the goal's velocity
  /// plus a proportional pull (the paper's aim law when the goal is the aim pose).
  void advance(const AimPose& goal, const Eigen::Vector3d& goal_velocity, double dt);
  /// Moves the reference dt seconds at `wanted_velocity` (limited), turning towards `yaw`.
  void steer(const Eigen::Vector3d& wanted_velocity, double yaw, double dt);
  /// Stops where it is (velocity ramps down at the acceleration limit); `yaw_rate` turns it.
  void hold(double dt, double yaw_rate = 0.0);

  const Eigen::Vector3d& position() const { return position_; }
  const Eigen::Vector3d& velocity() const { return velocity_; }
  const Eigen::Vector3d& acceleration() const { return acceleration_; }
  double yaw() const { return yaw_; }
  double yaw_rate() const { return yaw_rate_; }
  const Limits& limits() const { return limits_; }

 private:
  void move(const Eigen::Vector3d& wanted_velocity, double dt);
  void turn_to(double yaw, double dt);

  Limits limits_;
  Eigen::Vector3d position_, velocity_ = Eigen::Vector3d::Zero(), acceleration_ = Eigen::Vector3d::Zero();
  double yaw_, yaw_rate_ = 0.0;
};

}  // namespace kestrel::guidance
