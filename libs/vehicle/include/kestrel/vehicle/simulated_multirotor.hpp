#pragma once
// A simulated multirotor as a node flies it: the rigid body (MultirotorDynamics) in its wind,
// over its ground, stepped with whole RK4 steps up to the node's clock, commanded by rotor speeds
// or by a body wrench allocated to the rotors. On the way it keeps what a flight report gives
// (time in the air, distance, top speed, largest tilt, touchdowns). quadrotor_sim flies it by a
// controller's rotor speeds; sim_autopilot by its own attitude and rate loops.
#include <Eigen/Core>
#include <functional>
#include <kestrel/config_spec.hpp>
#include <kestrel/messages/vehicle_state.hpp>
#include <kestrel/node.hpp>

#include "kestrel/vehicle/multirotor_dynamics.hpp"
#include "kestrel/vehicle/rotor_mixer.hpp"
#include "kestrel/vehicle/wind.hpp"

namespace kestrel::vehicle {

/// Where and in what the vehicle flies (the vehicle itself is a MultirotorConfig).
struct SimulationConfig {
  double integration_hz = 1000.0;
  Eigen::Vector3d initial_position_m{0.0, 0.0, 0.0};
  double initial_yaw_deg = 0.0;
  double gravity_m_s2 = 9.81;
  double ground_z_m = 0.0;
  bool ground = true;
  Eigen::Vector3d wind_m_s{0.0, 0.0, 0.0};
  double gust_std_m_s = 0.0;
  double gust_time_constant_s = 2.0;
};

/// Declares the SimulationConfig fields of `group` in c.
template <class Config>
void declare_simulation(ConfigSpec<Config>& c, SimulationConfig Config::*group) {
  using S = SimulationConfig;
  c.param("integration_hz", group, &S::integration_hz)
      .with_unit("Hz")
      .range(500.0, 100000.0)
      .describe("RK4 steps per second (sub-steps between ticks)");
  c.param("initial_position_m", group, &S::initial_position_m).with_unit("m").describe("start position (world, z up)");
  c.param("initial_yaw_deg", group, &S::initial_yaw_deg)
      .with_unit("deg")
      .range(-360.0, 360.0)
      .describe("start heading");
  c.param("gravity_m_s2", group, &S::gravity_m_s2).with_unit("m/s^2").range(0.0, 100.0).describe("gravity, along -z");
  c.param("ground", group, &S::ground).describe("a flat ground the vehicle rests on and cannot go through");
  c.param("ground_z_m", group, &S::ground_z_m).with_unit("m").describe("height of the ground");
  c.param("wind_m_s", group, &S::wind_m_s).with_unit("m/s").range(-50.0, 50.0).describe("mean wind (world)");
  c.param("gust_std_m_s", group, &S::gust_std_m_s)
      .with_unit("m/s")
      .range(0.0, 50.0)
      .describe("gusts: standard deviation of each wind component about the mean");
  c.param("gust_time_constant_s", group, &S::gust_time_constant_s)
      .with_unit("s")
      .range(0.01, 1000.0)
      .describe("gusts: correlation time");
}

/// What a flight report gives.
struct FlightRecord {
  double flight_time_s = 0.0;
  double distance_m = 0.0;
  double max_speed_m_s = 0.0;
  double max_tilt_deg = 0.0;
  std::uint64_t touchdowns = 0;
};

class SimulatedMultirotor {
 public:
  SimulatedMultirotor(const Multirotor& vehicle, const SimulationConfig& config, std::uint64_t seed);

  /// Rotor speeds to follow from now on (rad/s). Throws Error for a wrong count or a non-finite speed.
  void command_rotor_speeds(const Eigen::VectorXd& speeds);
  /// Collective thrust (N, along body z) and body torques (N m), allocated to the rotors and
  /// clipped to their range (RotorMixer). Throws Error for a non-finite value.
  void command_wrench(double thrust_n, const Eigen::Vector3d& torque_nm);

  /// Whole RK4 steps up to t_s (seconds of the node's clock); the remainder carries over.
  /// `before_step`, if given, runs before each step with the simulated time (a controller that
  /// commands at the integration rate). Throws Error once the state is no longer finite.
  void advance_to(double t_s, const std::function<void(double)>& before_step = {});

  const RigidBodyState& state() const { return state_; }
  /// The state as a message, stamped.
  msg::VehicleState vehicle_state(Time stamp) const;
  bool on_ground() const { return dynamics_.on_ground(); }
  double simulated_s() const { return simulated_; }
  double step_s() const { return step_; }
  const Multirotor& vehicle() const { return dynamics_.vehicle(); }
  const FlightRecord& record() const { return record_; }
  /// The largest collective thrust, every rotor at its top speed (N).
  double max_thrust_n() const;

 private:
  void account(double dt);

  MultirotorDynamics dynamics_;
  Wind wind_;
  Environment env_;
  RigidBodyState state_;
  Eigen::VectorXd command_;
  RotorMixer mixer_;
  double step_;
  double simulated_ = 0.0;
  bool was_on_ground_ = false;
  FlightRecord record_;
};

/// The node's report section for a flight (flight_time_s, distance_m, max_speed_m_s,
/// max_tilt_deg, touchdowns, final_position_m) added to the node's own `section`, with a line of
/// summary followed by `more_summary`.
void report_flight(Context& ctx, const SimulatedMultirotor& flight, ReportSection section = {},
                   const std::string& more_summary = "");

}  // namespace kestrel::vehicle
