#pragma once
// The simulated autopilot's own flight control, cascaded as PX4's multicopter controllers are
// (mc_pos_control, mc_att_control, mc_rate_control), in physical units and kestrel's frames
// (world ENU, body FLU):
//   position P -> velocity PID -> acceleration -> thrust vector and attitude (tilt limited)
//   attitude P on the quaternion error -> body rates (limited) -> rate PID -> body torques.
// Defaults are PX4's multicopter defaults where PX4 states them in these units (MPC_XY_P,
// MPC_Z_P, MPC_*_VEL_*_ACC, MPC_TILTMAX_AIR, MC_*_P, MC_*RATE_MAX); the rate gains, which PX4
// gives in normalised actuator units, are angular accelerations per rad/s of rate error here.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <kestrel/vehicle/multirotor.hpp>
#include <kestrel/vehicle/multirotor_dynamics.hpp>
#include <optional>

namespace kestrel::sim_autopilot {

struct FlightControlGains {
  Eigen::Vector3d position_p{0.95, 0.95, 1.0};          ///< 1/s (MPC_XY_P, MPC_Z_P)
  Eigen::Vector3d velocity_p{1.8, 1.8, 4.0};            ///< 1/s (MPC_XY_VEL_P_ACC, MPC_Z_VEL_P_ACC)
  Eigen::Vector3d velocity_i{0.4, 0.4, 2.0};            ///< 1/s^2 (MPC_XY_VEL_I_ACC, MPC_Z_VEL_I_ACC)
  Eigen::Vector3d velocity_d{0.2, 0.2, 0.0};            ///< dimensionless (MPC_XY_VEL_D_ACC, MPC_Z_VEL_D_ACC)
  double max_speed_xy_m_s = 12.0;                       ///< MPC_XY_VEL_MAX
  double max_speed_up_m_s = 3.0;                        ///< MPC_Z_VEL_MAX_UP
  double max_speed_down_m_s = 1.5;                      ///< MPC_Z_VEL_MAX_DN
  double max_tilt_deg = 45.0;                           ///< MPC_TILTMAX_AIR
  Eigen::Vector3d attitude_p{6.5, 6.5, 2.8};            ///< 1/s (MC_ROLL_P, MC_PITCH_P, MC_YAW_P)
  Eigen::Vector3d max_rate_deg_s{220.0, 220.0, 200.0};  ///< MC_ROLLRATE_MAX, MC_PITCHRATE_MAX, MC_YAWRATE_MAX
  Eigen::Vector3d rate_p{25.0, 25.0, 10.0};             ///< rad/s^2 per rad/s
  Eigen::Vector3d rate_i{10.0, 10.0, 4.0};              ///< rad/s^2 per rad
  Eigen::Vector3d rate_d{0.0, 0.0, 0.0};                ///< rad/s^2 per rad/s^2
};

/// A position target as MAVLink's SET_POSITION_TARGET_LOCAL_NED gives one (ENU here); a part
/// the type mask ignores is left out.
struct PositionTarget {
  std::optional<Eigen::Vector3d> position, velocity, acceleration;
  std::optional<double> yaw;  ///< ENU, rad
};

/// An attitude target as SET_ATTITUDE_TARGET gives one (body to world ENU/FLU).
struct AttitudeCommand {
  std::optional<Eigen::Quaterniond> orientation;         ///< left out: rates only
  Eigen::Vector3d body_rates = Eigen::Vector3d::Zero();  ///< feed-forward (or the target itself)
  double thrust_n = 0.0;
};

struct BodyWrench {
  double thrust_n = 0.0;
  Eigen::Vector3d torque_nm = Eigen::Vector3d::Zero();
};

class FlightControl {
 public:
  FlightControl(const vehicle::Multirotor& vehicle, FlightControlGains gains, double gravity, double max_thrust_n);

  /// The wrench that flies to `target`, dt after the last call.
  BodyWrench position(const PositionTarget& target, const vehicle::RigidBodyState& s, double dt);
  /// The wrench that holds `command`'s attitude and thrust.
  BodyWrench attitude(const AttitudeCommand& command, const vehicle::RigidBodyState& s, double dt);
  /// Forgets the integrators (on the ground, or when the kind of command changes).
  void reset();

 private:
  Eigen::Vector3d rate_setpoint(const Eigen::Quaterniond& desired, const vehicle::RigidBodyState& s) const;
  Eigen::Vector3d torque(const Eigen::Vector3d& rate_sp, const vehicle::RigidBodyState& s, double dt);

  vehicle::Multirotor vehicle_;
  FlightControlGains gains_;
  double gravity_, max_thrust_n_;
  Eigen::Vector3d velocity_integral_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d rate_integral_ = Eigen::Vector3d::Zero();
  std::optional<Eigen::Vector3d> last_velocity_error_, last_rate_error_;
};

}  // namespace kestrel::sim_autopilot
