#pragma once
// The geometric tracking controller on SE(3) of Lee, Leok & McClamroch (2010), in the form of
// RotorS' lee_position_controller: from a position/velocity/acceleration/yaw setpoint and the
// vehicle's state to a desired force, a desired attitude, a collective thrust and body torques,
// then rotor speeds through the inverse of the rotor allocation.
//
// World z up, body FLU; positions and velocities in the world frame, body rates in the body frame.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <kestrel/messages/trajectory_setpoint.hpp>
#include <kestrel/messages/vehicle_state.hpp>
#include <kestrel/vehicle/multirotor.hpp>
#include <kestrel/vehicle/rotor_mixer.hpp>

namespace kestrel::control {

/// Firefly gains (RotorS lee_controller_firefly.yaml). Position and velocity gains act on force
/// (N/m, N s/m); attitude and rate gains on torque (N m/rad, N m s/rad).
struct LeeGains {
  Eigen::Vector3d position{6.0, 6.0, 6.0};
  Eigen::Vector3d velocity{4.7, 4.7, 4.7};
  Eigen::Vector3d attitude{3.0, 3.0, 0.15};
  Eigen::Vector3d angular_rate{0.52, 0.52, 0.18};
};

struct LeeCommand {
  Eigen::Vector3d force_world = Eigen::Vector3d::Zero();   ///< desired total force, after the tilt limit
  Eigen::Matrix3d attitude = Eigen::Matrix3d::Identity();  ///< desired rotation, body to world
  Eigen::Vector3d body_rates = Eigen::Vector3d::Zero();    ///< desired, in the desired body frame
  Eigen::Vector3d attitude_error = Eigen::Vector3d::Zero();
  Eigen::Vector3d rate_error = Eigen::Vector3d::Zero();
  double thrust_n = 0.0;                                ///< along the current body z
  Eigen::Vector3d torque_nm = Eigen::Vector3d::Zero();  ///< body
  Eigen::VectorXd rotor_speeds;                         ///< rad/s, within [0, max]
  bool saturated = false;  ///< a rotor speed was clipped to its range, or the tilt limit acted
};

class LeePositionControl {
 public:
  LeePositionControl(vehicle::Multirotor vehicle, LeeGains gains, double gravity = 9.81,
                     double max_tilt_rad = M_PI / 3.0,
                     vehicle::RotorMixer::Priority mixer = vehicle::RotorMixer::Priority::clip);

  LeeCommand compute(const msg::TrajectorySetpoint& setpoint, const msg::VehicleState& state) const;

  /// Rotor speeds that produce body torques and a collective thrust within the motors' range
  /// (vehicle::RotorMixer: clipped, or attitude first).
  Eigen::VectorXd allocate(const Eigen::Vector3d& torque, double thrust, bool* saturated = nullptr) const;

  /// Lee's attitude error e_R = vee(R_d^T R - R^T R_d) / 2.
  static Eigen::Vector3d attitude_error(const Eigen::Matrix3d& desired, const Eigen::Matrix3d& actual);

  const vehicle::Multirotor& vehicle() const { return vehicle_; }
  double hover_thrust_n() const { return vehicle_.mass_kg * gravity_; }

 private:
  vehicle::Multirotor vehicle_;
  LeeGains gains_;
  double gravity_;
  double max_tilt_rad_;
  vehicle::RotorMixer mixer_;
};

}  // namespace kestrel::control
