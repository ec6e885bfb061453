// The `lee_controller` node: Lee's geometric controller between a trajectory setpoint and the
// vehicle. Each odometry message yields one command, as rotor speeds (`command`, for the
// simulator or a motor-level link) and as attitude, body rates and thrust (`attitude`, for an
// autopilot that closes its own attitude loop). A setpoint or a state that is not finite never
// reaches the motors: the command falls back to a safe hover or to cut motors, and is counted.
#include <fmt/format.h>

#include <kestrel/geometry/frames.hpp>
#include <kestrel/messages/actuator_command.hpp>
#include <kestrel/messages/attitude_target.hpp>
#include <kestrel/messages/trajectory_setpoint.hpp>
#include <kestrel/messages/vehicle_state.hpp>
#include <kestrel/plugin.hpp>
#include <kestrel/vehicle/multirotor_config.hpp>
#include <optional>

#include "lee_position_control.hpp"

namespace kestrel::control {

struct LeeControllerConfig {
  enum class OnFault { hover, cut };
  Eigen::Vector3d position_gain{6.0, 6.0, 6.0};
  Eigen::Vector3d velocity_gain{4.7, 4.7, 4.7};
  Eigen::Vector3d attitude_gain{3.0, 3.0, 0.15};
  Eigen::Vector3d angular_rate_gain{0.52, 0.52, 0.18};
  double max_tilt_deg = 60.0;
  double gravity_m_s2 = 9.81;
  vehicle::MultirotorConfig vehicle;
  OnFault on_fault = OnFault::hover;
  vehicle::RotorMixer::Priority mixer = vehicle::RotorMixer::Priority::clip;
};

namespace {

bool finite(const msg::TrajectorySetpoint& s) {
  return s.position.allFinite() && s.velocity.allFinite() && s.acceleration.allFinite() && std::isfinite(s.yaw) &&
         std::isfinite(s.yaw_rate);
}

bool finite(const msg::VehicleState& s) {
  return s.position.allFinite() && s.velocity.allFinite() && s.orientation.coeffs().allFinite() &&
         s.orientation.norm() > 0.5 && s.angular_velocity.allFinite();
}

}  // namespace

class LeeControllerNode final : public Node {
 public:
  static constexpr Input<msg::VehicleState> kOdometry{"odometry"};
  static constexpr Input<msg::TrajectorySetpoint> kSetpoint{"setpoint"};
  static constexpr Output<msg::ActuatorCommand> kCommand{"command"};
  static constexpr Output<msg::AttitudeTarget> kAttitude{"attitude"};

  static NodeSpec spec() {
    using C = LeeControllerConfig;
    ConfigSpec<C> c;
    c.param("position_gain", &C::position_gain)
        .with_unit("N/m")
        .range(0.0, 1000.0)
        .describe("k_x, per world axis (the default: the airframe's)");
    c.param("velocity_gain", &C::velocity_gain)
        .with_unit("N s/m")
        .range(0.0, 1000.0)
        .describe("k_v, per world axis (the default: the airframe's)");
    c.param("attitude_gain", &C::attitude_gain)
        .with_unit("N m/rad")
        .range(0.0, 1000.0)
        .describe("k_R, per body axis (the default: the airframe's)");
    c.param("angular_rate_gain", &C::angular_rate_gain)
        .with_unit("N m s/rad")
        .range(0.0, 1000.0)
        .describe("k_Omega, per body axis (the default: the airframe's)");
    c.param("max_tilt_deg", &C::max_tilt_deg)
        .with_unit("deg")
        .range(1.0, 89.0)
        .describe("the desired thrust direction stays within this angle of vertical (60: the airframe's)");
    c.param("gravity_m_s2", &C::gravity_m_s2).with_unit("m/s^2").range(0.0, 100.0).describe("gravity, along -z");
    vehicle::declare_multirotor(c, &C::vehicle);
    c.choice("mixer", &C::mixer,
             {{"clip", vehicle::RotorMixer::Priority::clip}, {"attitude", vehicle::RotorMixer::Priority::attitude}})
        .describe(
            "when the motors cannot give the wrench: clip each rotor to its range (RotorS's; the thrust stays and the "
            "attitude overshoots its limit) or keep the attitude (PX4's mixer: the thrust gives way, then yaw, then "
            "roll and pitch)");
    c.choice("on_fault", &C::on_fault, {{"hover", C::OnFault::hover}, {"cut", C::OnFault::cut}})
        .describe(
            "when the setpoint or the state is not finite: hover (hold the last good setpoint; without a good "
            "state, every rotor at hover speed) or cut (every rotor stopped)");
    return NodeSpec("lee_controller", "Lee geometric position controller (SE(3)) with rotor allocation")
        .details(
            "Lee, Leok & McClamroch (2010) as RotorS implements it, with Firefly gains. Runs once per odometry "
            "message against the latest setpoint; until the first setpoint the motors stay still. World frame z up, "
            "body FLU. The vehicle parameters must describe the vehicle flown (they default to the simulator's). "
            "The gains and the tilt limit left at their defaults (the Firefly's) are the airframe's, tuned for it.")
        .input(kOdometry, "the vehicle's state")
        .input(kSetpoint, "where the vehicle should be", {.trigger = Trigger::latest, .optional = true})
        .output(kCommand, "rotor speeds, with the thrust and torques they make")
        .output(kAttitude, "the same command as attitude, body rates and collective thrust")
        .config(std::move(c));
  }

  explicit LeeControllerNode(NodeInit& init) : LeeControllerNode(init.config<LeeControllerConfig>()) {}

  void process(Context& ctx) override {
    const auto state = ctx.get(kOdometry);
    const auto setpoint = ctx.get(kSetpoint);
    ++commands_;
    msg::ActuatorCommand command;
    msg::AttitudeTarget attitude;
    command.stamp = attitude.stamp = state->stamp;
    attitude.hover_thrust_n = control_.hover_thrust_n();
    const auto rotors = static_cast<Eigen::Index>(control_.vehicle().rotors.size());

    const bool good_state = finite(*state);
    if (setpoint && finite(*setpoint)) last_good_ = *setpoint;
    if (setpoint && !finite(*setpoint)) fault(ctx, bad_setpoints_, "setpoint");
    if (!good_state) fault(ctx, bad_states_, "state");

    Eigen::VectorXd speeds = Eigen::VectorXd::Zero(rotors);
    const bool cut = cfg_.on_fault == LeeControllerConfig::OnFault::cut;
    if (!good_state) {
      // Nothing to close a loop on: level hover thrust, or nothing.
      if (!cut) speeds.setConstant(control_.vehicle().hover_rotor_speed_rad_s(cfg_.gravity_m_s2));
      attitude.thrust_n = cut ? 0.0 : control_.hover_thrust_n();
      command.thrust_n = attitude.thrust_n;
    } else if (setpoint && (finite(*setpoint) || (!cut && last_good_))) {
      const LeeCommand lee = control_.compute(*last_good_, *state);
      speeds = lee.rotor_speeds;
      if (lee.saturated) ++saturated_;
      command.thrust_n = attitude.thrust_n = lee.thrust_n;
      command.torque_nm = lee.torque_nm;
      attitude.orientation = Eigen::Quaterniond(lee.attitude);
      attitude.body_rates = lee.body_rates;
    } else if (setpoint && !cut) {
      // A bad setpoint before any good one: hold where the vehicle is.
      msg::TrajectorySetpoint hold;
      hold.position = state->position;
      hold.yaw = geometry::yaw_of(state->orientation);
      last_good_ = hold;
      const LeeCommand lee = control_.compute(hold, *state);
      speeds = lee.rotor_speeds;
      command.thrust_n = attitude.thrust_n = lee.thrust_n;
      command.torque_nm = lee.torque_nm;
      attitude.orientation = Eigen::Quaterniond(lee.attitude);
    }
    if (!speeds.allFinite()) {  // cannot happen from finite inputs; never let it through if it does
      fault(ctx, bad_outputs_, "computed command");
      speeds = Eigen::VectorXd::Zero(rotors);
    }
    command.rotor_speeds_rad_s.assign(speeds.data(), speeds.data() + speeds.size());
    ctx.publish(kCommand, std::move(command));
    ctx.publish(kAttitude, std::move(attitude));
  }

  void finish(Context& ctx) override {
    const std::string id = ctx.id();
    const std::uint64_t faults = bad_setpoints_ + bad_states_ + bad_outputs_;
    ctx.set_report_section(
        id, ReportSection()
                .quantity("commands", commands_)
                .metric("saturated_commands", saturated_, "", Better::lower)
                .metric("faults", faults, "", Better::lower)
                .metric("bad_setpoints", bad_setpoints_, "", Better::lower)
                .metric("bad_states", bad_states_, "", Better::lower)
                .markdown(
                    fmt::format("{} commands, {} saturated; {} fault(s) handled by {} ({} bad setpoint(s), {} "
                                "bad state(s)).\n",
                                commands_, saturated_, faults,
                                cfg_.on_fault == LeeControllerConfig::OnFault::cut ? "cutting the motors" : "hovering",
                                bad_setpoints_, bad_states_)));
  }

 private:
  explicit LeeControllerNode(const LeeControllerConfig& cfg)
      : cfg_(cfg),
        control_(cfg.vehicle.multirotor(), gains_for(cfg), cfg.gravity_m_s2, tilt_for(cfg) * M_PI / 180.0, cfg.mixer) {}

  // A gain left at its default is the airframe's own; one set to anything else is the user's.
  static LeeGains gains_for(const LeeControllerConfig& cfg) {
    const LeeControllerConfig defaults{};
    const vehicle::LeeGainSet& tuned = vehicle::airframe(cfg.vehicle.airframe).gains;
    const auto pick = [](const Eigen::Vector3d& given, const Eigen::Vector3d& fallback, const Eigen::Vector3d& own) {
      return given != fallback ? given : own;
    };
    return LeeGains{pick(cfg.position_gain, defaults.position_gain, tuned.position),
                    pick(cfg.velocity_gain, defaults.velocity_gain, tuned.velocity),
                    pick(cfg.attitude_gain, defaults.attitude_gain, tuned.attitude),
                    pick(cfg.angular_rate_gain, defaults.angular_rate_gain, tuned.angular_rate)};
  }
  static double tilt_for(const LeeControllerConfig& cfg) {
    return cfg.max_tilt_deg != LeeControllerConfig{}.max_tilt_deg
               ? cfg.max_tilt_deg
               : vehicle::airframe(cfg.vehicle.airframe).envelope.max_tilt_deg;
  }

  void fault(Context& ctx, std::uint64_t& counter, const char* what) {
    if (counter++ == 0)
      ctx.log().warn("the {} is not finite at t = {:.3f} s; {} (counted in the report)", what, to_seconds(ctx.now()),
                     cfg_.on_fault == LeeControllerConfig::OnFault::cut ? "motors cut" : "hovering");
  }

  LeeControllerConfig cfg_;
  LeePositionControl control_;
  std::optional<msg::TrajectorySetpoint> last_good_;
  std::uint64_t commands_ = 0, saturated_ = 0, bad_setpoints_ = 0, bad_states_ = 0, bad_outputs_ = 0;
};
KESTREL_REGISTER_NODE(LeeControllerNode)

}  // namespace kestrel::control
