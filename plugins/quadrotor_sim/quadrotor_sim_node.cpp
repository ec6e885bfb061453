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
#include <random>

#include "multirotor_dynamics.hpp"
#include "wind.hpp"

namespace kestrel::quadrotor {

struct QuadrotorSimConfig {
  double rate_hz = 100.0;
  double integration_hz = 1000.0;
  Eigen::Vector3d initial_position_m{0.0, 0.0, 0.0};
  double initial_yaw_deg = 0.0;
  double gravity_m_s2 = 9.81;
  double ground_z_m = 0.0;
  bool ground = true;
  vehicle::MultirotorConfig vehicle;
  Eigen::Vector3d wind_m_s{0.0, 0.0, 0.0};
  double gust_std_m_s = 0.0;
  double gust_time_constant_s = 2.0;
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
    c.param("integration_hz", &C::integration_hz)
        .with_unit("Hz")
        .range(500.0, 100000.0)
        .describe("RK4 steps per second (sub-steps between ticks)");
    c.param("initial_position_m", &C::initial_position_m).with_unit("m").describe("start position (world, z up)");
    c.param("initial_yaw_deg", &C::initial_yaw_deg).with_unit("deg").range(-360.0, 360.0).describe("start heading");
    c.param("gravity_m_s2", &C::gravity_m_s2).with_unit("m/s^2").range(0.0, 100.0).describe("gravity, along -z");
    c.param("ground", &C::ground).describe("a flat ground the vehicle rests on and cannot go through");
    c.param("ground_z_m", &C::ground_z_m).with_unit("m").describe("height of the ground");
    vehicle::declare_multirotor(c, &C::vehicle);
    c.param("wind_m_s", &C::wind_m_s).with_unit("m/s").range(-50.0, 50.0).describe("mean wind (world)");
    c.param("gust_std_m_s", &C::gust_std_m_s)
        .with_unit("m/s")
        .range(0.0, 50.0)
        .describe("gusts: standard deviation of each wind component about the mean");
    c.param("gust_time_constant_s", &C::gust_time_constant_s)
        .with_unit("s")
        .range(0.01, 1000.0)
        .describe("gusts: correlation time");
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
           [](const C& k) { return k.integration_hz >= k.rate_hz; });
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
    const double now = to_seconds(ctx.now());
    apply(ctx.get(kCommand));
    // Whole RK4 steps up to now; the remainder carries over to the next tick.
    while (simulated_ + step_ <= now + 1e-12) {
      env_.wind = wind_.advance(step_);
      dynamics_.step(state_, command_, env_, step_);
      simulated_ += step_;
      account(step_);
    }
    if (!state_.position.allFinite() || !state_.orientation.coeffs().allFinite())
      throw Error(fmt::format("the simulated vehicle's state is no longer finite at t = {:.3f} s", now));
    msg::VehicleState truth = vehicle_state(ctx.now());
    ctx.publish(kOdometry, noisy(truth));
    ctx.publish(kState, std::move(truth));
  }

  void finish(Context& ctx) override {
    const std::string id = ctx.id();
    ctx.set_report_section(
        id,
        {{"flight_time_s", flight_time_s_},
         {"distance_m", distance_m_},
         {"max_speed_m_s", max_speed_},
         {"max_tilt_deg", max_tilt_deg_},
         {"touchdowns", touchdowns_},
         {"final_position_m", {{"x", state_.position.x()}, {"y", state_.position.y()}, {"z", state_.position.z()}}}},
        fmt::format("{:.1f} s in the air, {:.1f} m flown, top speed {:.2f} m/s, largest tilt "
                    "{:.1f} deg, {} touchdown(s).\n",
                    flight_time_s_, distance_m_, max_speed_, max_tilt_deg_, touchdowns_));
    ctx.describe_quantity(id + ".flight_time_s", "s");
    ctx.describe_quantity(id + ".distance_m", "m");
    ctx.describe_quantity(id + ".max_speed_m_s", "m/s");
    ctx.describe_quantity(id + ".max_tilt_deg", "deg");
    ctx.describe_quantity(id + ".touchdowns");
    ctx.describe_quantity(id + ".final_position_m", "m");
  }

 private:
  QuadrotorSimNode(NodeInit& init, const QuadrotorSimConfig& cfg)
      : cfg_(cfg),
        dynamics_(cfg.vehicle.multirotor()),
        wind_(cfg.wind_m_s, cfg.gust_std_m_s, cfg.gust_time_constant_s, init.seed()),
        noise_(init.seed() ^ 0x9e3779b97f4a7c15ull),
        step_(1.0 / cfg.integration_hz) {
    env_.gravity = cfg.gravity_m_s2;
    env_.ground_z = cfg.ground ? cfg.ground_z_m : -std::numeric_limits<double>::infinity();
    env_.wind = wind_.current();
    state_.position = cfg.initial_position_m;
    if (cfg.ground && state_.position.z() < cfg.ground_z_m) state_.position.z() = cfg.ground_z_m;
    state_.orientation = Eigen::AngleAxisd(cfg.initial_yaw_deg * M_PI / 180.0, Eigen::Vector3d::UnitZ());
    const auto rotors = static_cast<Eigen::Index>(dynamics_.vehicle().rotors.size());
    state_.rotor_speeds = Eigen::VectorXd::Zero(rotors);
    command_ = Eigen::VectorXd::Zero(rotors);
    allocation_ = dynamics_.vehicle().wrench_matrix().completeOrthogonalDecomposition().pseudoInverse();
    was_on_ground_ = cfg.ground && state_.position.z() <= cfg.ground_z_m;
    init.set_rate(cfg.rate_hz);
  }

  // The rotor speeds to follow: given directly, or allocated from thrust and torques.
  void apply(const std::shared_ptr<const msg::ActuatorCommand>& cmd) {
    if (!cmd) return;
    const auto rotors = command_.size();
    if (!cmd->rotor_speeds_rad_s.empty()) {
      if (static_cast<Eigen::Index>(cmd->rotor_speeds_rad_s.size()) != rotors)
        throw Error(fmt::format("command has {} rotor speeds; this vehicle has {} rotors",
                                cmd->rotor_speeds_rad_s.size(), rotors));
      command_ = Eigen::Map<const Eigen::VectorXd>(cmd->rotor_speeds_rad_s.data(), rotors);
    } else {
      Eigen::Vector4d wrench;
      wrench << cmd->torque_nm, cmd->thrust_n;
      command_ = (allocation_ * wrench).cwiseMax(0.0).cwiseSqrt();
    }
    if (!command_.allFinite()) throw Error("command holds a rotor speed that is not a finite number");
  }

  void account(double dt) {
    const bool grounded = dynamics_.on_ground();
    if (grounded && !was_on_ground_) ++touchdowns_;
    was_on_ground_ = grounded;
    if (grounded) return;
    flight_time_s_ += dt;
    distance_m_ += state_.velocity.norm() * dt;
    max_speed_ = std::max(max_speed_, state_.velocity.norm());
    const double tilt = std::acos(std::clamp((state_.orientation * Eigen::Vector3d::UnitZ()).z(), -1.0, 1.0));
    max_tilt_deg_ = std::max(max_tilt_deg_, tilt * 180.0 / M_PI);
  }

  msg::VehicleState vehicle_state(Time stamp) const {
    msg::VehicleState s;
    s.stamp = stamp;
    s.position = state_.position;
    s.velocity = state_.velocity;
    s.orientation = state_.orientation;
    s.angular_velocity = state_.angular_velocity;
    return s;
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
  MultirotorDynamics dynamics_;
  Wind wind_;
  std::mt19937_64 noise_;
  std::normal_distribution<double> normal_{0.0, 1.0};
  Environment env_;
  RigidBodyState state_;
  Eigen::VectorXd command_;
  Eigen::MatrixXd allocation_;
  double step_;
  double simulated_ = 0.0;
  bool was_on_ground_ = false;
  double flight_time_s_ = 0.0, distance_m_ = 0.0, max_speed_ = 0.0, max_tilt_deg_ = 0.0;
  std::uint64_t touchdowns_ = 0;
};
KESTREL_REGISTER_NODE(QuadrotorSimNode)

}  // namespace kestrel::quadrotor
