#pragma once
// Rigid-body dynamics of a multirotor: 6 degrees of freedom plus first-order motor lag, integrated
// with classic Runge-Kutta (RK4), with rotor drag against the air and a flat ground it rests on.
//
// World frame z up (gravity -z), body frame FLU. State: position and velocity in the world,
// attitude as the body-to-world quaternion, body rates, and the speed of each rotor.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <limits>

#include "kestrel/vehicle/multirotor.hpp"

namespace kestrel::vehicle {

struct RigidBodyState {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();               ///< world, m
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();               ///< world, m/s
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  ///< body to world
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();       ///< body, rad/s
  Eigen::VectorXd rotor_speeds;                                     ///< rad/s, one per rotor
};

/// What acts on the vehicle besides its rotors.
struct Environment {
  double gravity = 9.81;
  Eigen::Vector3d wind = Eigen::Vector3d::Zero();  ///< world, m/s
  /// Height of the ground plane; -infinity for none (free flight).
  double ground_z = 0.0;
};

class MultirotorDynamics {
 public:
  explicit MultirotorDynamics(Multirotor vehicle);

  /// Advances `s` by dt with the motors driven towards `commanded` (rad/s, clamped to the motor
  /// range): one RK4 step, then ground contact.
  void step(RigidBodyState& s, const Eigen::VectorXd& commanded, const Environment& env, double dt) const;

  /// Body force (thrust and rotor drag) and body torque produced by the rotors at their speeds.
  struct Wrench {
    Eigen::Vector3d force = Eigen::Vector3d::Zero();
    Eigen::Vector3d torque = Eigen::Vector3d::Zero();
  };
  Wrench rotor_wrench(const RigidBodyState& s, const Eigen::Vector3d& wind) const;

  /// True while the vehicle rests on the ground (after the last step).
  bool on_ground() const { return on_ground_; }
  const Multirotor& vehicle() const { return vehicle_; }

 private:
  struct Derivative {
    Eigen::Vector3d position, velocity;
    Eigen::Vector4d orientation;  ///< of the quaternion's coefficients (x, y, z, w)
    Eigen::Vector3d angular_velocity;
    Eigen::VectorXd rotor_speeds;
  };
  Derivative derivative(const RigidBodyState& s, const Eigen::VectorXd& commanded, const Environment& env) const;
  static RigidBodyState advanced(const RigidBodyState& s, const Derivative& d, double h);
  void contact(RigidBodyState& s, const Environment& env) const;

  Multirotor vehicle_;
  Eigen::MatrixXd wrench_matrix_;
  Eigen::Vector3d inertia_, inverse_inertia_;
  mutable bool on_ground_ = false;
};

}  // namespace kestrel::vehicle
