// The simulated autopilot's flight control: hand-computed cases (hover, the attitude error's
// rates), then flying the simulated Firefly with it: take-off and a position step, a velocity
// command, an attitude and thrust command.
#include <gmock/gmock.h>

#include <cmath>
#include <kestrel/vehicle/simulated_multirotor.hpp>
#include <numbers>

#include "flight_control.hpp"

using namespace kestrel;
using namespace kestrel::sim_autopilot;

namespace {

const vehicle::Multirotor kFirefly = vehicle::Multirotor::firefly();
constexpr double g = 9.81;

double max_thrust() {
  return 6 * kFirefly.thrust_constant * kFirefly.max_rotor_speed_rad_s * kFirefly.max_rotor_speed_rad_s;
}

// Control at 500 Hz, physics at 1 kHz, as sim_autopilot runs them.
struct Flight {
  vehicle::SimulatedMultirotor sim;
  FlightControl control{kFirefly, FlightControlGains{}, g, max_thrust()};
  double t = 0.0;

  explicit Flight(const Eigen::Vector3d& start, bool ground = false) : sim(kFirefly, config(start, ground), 1) {}
  static vehicle::SimulationConfig config(const Eigen::Vector3d& start, bool ground) {
    vehicle::SimulationConfig c;
    c.initial_position_m = start;
    c.ground = ground;
    return c;
  }
  template <class Command>
  void fly(Command command, double seconds) {
    const double end = t + seconds;
    double next = t;
    sim.advance_to(end, [&](double now) {
      if (now + 1e-12 < next) return;
      next += 0.002;
      const BodyWrench w = command(sim.state());
      sim.command_wrench(w.thrust_n, w.torque_nm);
    });
    t = end;
  }
  void fly_to(const PositionTarget& target, double seconds) {
    fly([&](const vehicle::RigidBodyState& s) { return control.position(target, s, 0.002); }, seconds);
  }
};

PositionTarget at(const Eigen::Vector3d& p, double yaw = 0.0) {
  PositionTarget t;
  t.position = p;
  t.velocity = Eigen::Vector3d::Zero();
  t.yaw = yaw;
  return t;
}

}  // namespace

TEST(FlightControl, AtItsSetpointItAsksForTheWeightAndNoTorque) {
  FlightControl control(kFirefly, FlightControlGains{}, g, max_thrust());
  vehicle::RigidBodyState s;
  s.position = Eigen::Vector3d(1, 2, 3);
  const BodyWrench w = control.position(at({1, 2, 3}), s, 0.002);
  EXPECT_NEAR(w.thrust_n, kFirefly.mass_kg * g, 1e-9);
  EXPECT_LT(w.torque_nm.norm(), 1e-12);
}

TEST(FlightControl, AnAttitudeErrorTurnsIntoRatesAboutTheRightAxisWithinTheLimits) {
  FlightControlGains gains;
  FlightControl control(kFirefly, gains, g, max_thrust());
  vehicle::RigidBodyState s;
  AttitudeCommand c;
  // 0.1 rad of roll wanted: rate = 2 Kp sin(0.05) about body x, so a positive torque about x only.
  c.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitX()));
  c.thrust_n = 10.0;
  const BodyWrench w = control.attitude(c, s, 0.002);
  // The rate loop's first step: P on the rate error, plus one step of its integral.
  const double dt = 0.002, rate = 2 * gains.attitude_p.x() * std::sin(0.05);
  EXPECT_NEAR(w.torque_nm.x(), kFirefly.inertia_kg_m2.x() * (gains.rate_p.x() + gains.rate_i.x() * dt) * rate, 1e-12);
  EXPECT_NEAR(w.torque_nm.y(), 0.0, 1e-12);
  EXPECT_NEAR(w.torque_nm.z(), 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(w.thrust_n, 10.0);
  // Half a turn of yaw wanted: the rate is clamped to MC_YAWRATE_MAX.
  control.reset();
  c.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(3.0, Eigen::Vector3d::UnitZ()));
  const BodyWrench turn = control.attitude(c, s, 0.002);
  const double max_yaw_rate = gains.max_rate_deg_s.z() * std::numbers::pi / 180.0;
  EXPECT_NEAR(turn.torque_nm.z(),
              kFirefly.inertia_kg_m2.z() * (gains.rate_p.z() + gains.rate_i.z() * dt) * max_yaw_rate, 1e-12);
}

TEST(FlightControl, TakesOffFromTheGroundAndSettlesAStep) {
  Flight f({0, 0, 0}, true);
  f.fly_to(at({0, 0, 2}), 8.0);
  EXPECT_NEAR((f.sim.state().position - Eigen::Vector3d(0, 0, 2)).norm(), 0.0, 0.03);
  EXPECT_EQ(f.sim.record().touchdowns, 0u);
  f.fly_to(at({2, -1, 3}, 1.0), 10.0);
  EXPECT_NEAR((f.sim.state().position - Eigen::Vector3d(2, -1, 3)).norm(), 0.0, 0.03);
  const Eigen::Vector3d forward = f.sim.state().orientation * Eigen::Vector3d::UnitX();
  EXPECT_NEAR(std::atan2(forward.y(), forward.x()), 1.0, 0.01);
  EXPECT_LT(f.sim.record().max_tilt_deg, 45.5) << "MPC_TILTMAX_AIR";
}

TEST(FlightControl, FollowsAVelocityCommandWithinTheSpeedLimits) {
  Flight f({0, 0, 5});
  PositionTarget v;
  v.velocity = Eigen::Vector3d(3, 0, -4);  // down faster than MPC_Z_VEL_MAX_DN allows
  f.fly_to(v, 6.0);
  EXPECT_NEAR(f.sim.state().velocity.x(), 3.0, 0.05);
  EXPECT_NEAR(f.sim.state().velocity.z(), -FlightControlGains{}.max_speed_down_m_s, 0.05);
}

TEST(FlightControl, HoldsACommandedTiltAndThrust) {
  Flight f({0, 0, 50});
  AttitudeCommand c;
  c.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitY()));  // pitched: nose down
  c.thrust_n = kFirefly.mass_kg * g / std::cos(0.2);  // the vertical part holds the weight
  f.fly([&](const vehicle::RigidBodyState& s) { return f.control.attitude(c, s, 0.002); }, 3.0);
  EXPECT_LT(f.sim.state().orientation.angularDistance(*c.orientation), 0.01);
  EXPECT_NEAR(f.sim.state().velocity.z(), 0.0, 0.3);  // rotor drag and motor lag aside, level flight
  EXPECT_GT(f.sim.state().velocity.x(), 3.0);         // accelerating forward at g tan(0.2)
}
