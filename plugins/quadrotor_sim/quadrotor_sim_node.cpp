// The `quadrotor_sim` node: the simulated hunter. A multirotor flown by the rotor speeds that
// arrive on `command`, integrated with RK4 at integration_hz between its ticks, in gravity,
// wind and gusts, resting on a flat ground until its rotors lift it. Publishes its true state
// (for a camera riding on it) and odometry with optional noise (for the controller).
#include <fmt/format.h>

#include <cmath>
#include <kestrel/messages/actuator_command.hpp>
#include <kestrel/messages/vehicle_state.hpp>
#include <kestrel/plugin.hpp>
#include <kestrel/vehicle/multirotor_config.hpp>
#include <kestrel/vehicle/simulated_multirotor.hpp>
#include <random>

namespace kestrel::quadrotor {

struct QuadrotorSimConfig {
  double rate_hz = 100.0;
  vehicle::SimulationConfig sim;
  vehicle::MultirotorConfig vehicle;
  double position_noise_m = 0.0;
  double velocity_noise_m_s = 0.0;
  double attitude_noise_deg = 0.0;
  double rate_noise_rad_s = 0.0;
};

class QuadrotorSimNode final : public Node {
 public:
  static constexpr Input<msg::ActuatorCommand> kCommand{"command"};
  static constexpr Output<msg::VehicleState> kState{"state"};
  static constexpr Output<msg::VehicleState> kOdometry{"odometry"};

  static NodeSpec spec() {
    using C = QuadrotorSimConfig;
    ConfigSpec<C> c;
    c.param("rate_hz", &C::rate_hz).with_unit("Hz").range(1.0, 10000.0).describe("state and odometry rate");
    vehicle::declare_simulation(c, &C::sim);
    vehicle::declare_multirotor(c, &C::vehicle);
    c.param("position_noise_m", &C::position_noise_m)
        .with_unit("m")
        .range(0.0, 100.0)
        .describe("odometry: standard deviation of position noise, per axis");
    c.param("velocity_noise_m_s", &C::velocity_noise_m_s)
        .with_unit("m/s")
        .range(0.0, 100.0)
        .describe("odometry: standard deviation of velocity noise, per axis");
    c.param("attitude_noise_deg", &C::attitude_noise_deg)
        .with_unit("deg")
        .range(0.0, 90.0)
        .describe("odometry: standard deviation of attitude noise, per axis");
    c.param("rate_noise_rad_s", &C::rate_noise_rad_s)
        .with_unit("rad/s")
        .range(0.0, 100.0)
        .describe("odometry: standard deviation of body-rate noise, per axis");
    c.rule("integration_hz >= rate_hz", {"integration_hz", "rate_hz"},
           [](const C& k) { return k.sim.integration_hz >= k.rate_hz; });
    return NodeSpec("quadrotor_sim", "Simulated multirotor: 6-DoF rigid body, motor lag, rotor drag, wind, ground")
        .details(
            "RotorS Firefly hexacopter by default. The rotors follow the speeds of the latest `command` through "
            "first-order motor lag; without a command they are still. World frame z up, body frame FLU. "
            "`state` is the true state (for a camera riding on the vehicle), `odometry` the same with noise "
            "(for the controller). Deterministic for a given seed under lockstep.")
        .input(kCommand, "rotor speeds (or thrust and torques) to follow",
               {.trigger = Trigger::latest, .optional = true})
        .output(kState, "true state at rate_hz")
        .output(kOdometry, "state with odometry noise at rate_hz")
        .config(std::move(c));
  }

  explicit QuadrotorSimNode(NodeInit& init) : QuadrotorSimNode(init, init.config<QuadrotorSimConfig>()) {}

  void tick(Context& ctx) override {
    if (const auto cmd = ctx.get(kCommand)) apply(*cmd);
    flight_.advance_to(to_seconds(ctx.now()));
    msg::VehicleState truth = flight_.vehicle_state(ctx.now());
    ctx.publish(kOdometry, noisy(truth));
    ctx.publish(kState, std::move(truth));
  }

  void finish(Context& ctx) override { vehicle::report_flight(ctx, flight_); }

 private:
  QuadrotorSimNode(NodeInit& init, const QuadrotorSimConfig& cfg)
      : cfg_(cfg),
        flight_(cfg.vehicle.multirotor(), cfg.sim, init.seed()),
        noise_(init.seed() ^ 0x9e3779b97f4a7c15ull) {
    init.set_rate(cfg.rate_hz);
  }

  // The rotor speeds to follow: given directly, or allocated from thrust and torques.
  void apply(const msg::ActuatorCommand& cmd) {
    if (!cmd.rotor_speeds_rad_s.empty())
      flight_.command_rotor_speeds(Eigen::Map<const Eigen::VectorXd>(
          cmd.rotor_speeds_rad_s.data(), static_cast<Eigen::Index>(cmd.rotor_speeds_rad_s.size())));
    else
      flight_.command_wrench(cmd.thrust_n, cmd.torque_nm);
  }

  msg::VehicleState noisy(msg::VehicleState s) {
    auto gauss = [&](double sd) {
      return sd > 0.0 ? Eigen::Vector3d(sd * normal_(noise_), sd * normal_(noise_), sd * normal_(noise_))
                      : Eigen::Vector3d::Zero();
    };
    s.position += gauss(cfg_.position_noise_m);
    s.velocity += gauss(cfg_.velocity_noise_m_s);
    const Eigen::Vector3d tilt = gauss(cfg_.attitude_noise_deg * M_PI / 180.0);
    if (tilt.norm() > 0.0)
      s.orientation = (s.orientation * Eigen::AngleAxisd(tilt.norm(), tilt.normalized())).normalized();
    s.angular_velocity += gauss(cfg_.rate_noise_rad_s);
    return s;
  }

  QuadrotorSimConfig cfg_;
  vehicle::SimulatedMultirotor flight_;
  std::mt19937_64 noise_;
  std::normal_distribution<double> normal_{0.0, 1.0};
};
KESTREL_REGISTER_NODE(QuadrotorSimNode)

}  // namespace kestrel::quadrotor
