// The `sim_autopilot` node: a simulated PX4 vehicle on a MAVLink link, the partner of
// mavlink_sink and mavlink_source for software-in-the-loop runs without PX4. It flies the
// multirotor of quadrotor_sim (vehicle::SimulatedMultirotor) with its own cascade of position,
// attitude and rate loops (FlightControl), follows PX4's offboard rules (OffboardRules), and sends
// what PX4 sends a companion: HEARTBEAT at 1 Hz, LOCAL_POSITION_NED and ATTITUDE_QUATERNION at
// telemetry_hz, EXTENDED_SYS_STATE, STATUSTEXT on mode changes, a COMMAND_ACK for each command.
// The launcher hangs on a servo or relay output: setting it publishes a fire order. It publishes
// its true state for what rides on it (a simulated camera, the net). docs/field.md.
#include <fmt/format.h>

#include <kestrel/geometry/frames.hpp>
#include <kestrel/geometry/ned_enu.hpp>
#include <kestrel/messages/net_fire.hpp>
#include <kestrel/messages/vehicle_state.hpp>
#include <kestrel/plugin.hpp>
#include <kestrel/vehicle/multirotor_config.hpp>
#include <kestrel/vehicle/simulated_multirotor.hpp>
#include <memory>

#include "flight_control.hpp"
#include "kestrel/mavlink/connection_param.hpp"
#include "kestrel/mavlink/connection_url.hpp"
#include "kestrel/mavlink/frame_parser.hpp"
#include "kestrel/mavlink/signing_param.hpp"
#include "kestrel/mavlink/transport.hpp"
#include "offboard_rules.hpp"

namespace kestrel::sim_autopilot {

namespace mav = mavlink::mav;

struct SimAutopilotConfig {
  std::string connection = "udpout://127.0.0.1:14540";
  mavlink::SigningConfig signing;
  double rate_hz = 100.0;
  double telemetry_hz = 50.0;
  double control_hz = 500.0;
  double offboard_loss_timeout_s = 0.5;
  double min_setpoint_rate_hz = 2.0;
  double idle_speed_fraction = 0.1;
  enum class Launcher { servo, relay };
  Launcher launcher = Launcher::servo;
  std::int64_t launcher_channel = 9;
  double launcher_threshold = 1500.0;
  vehicle::SimulationConfig sim;
  vehicle::MultirotorConfig vehicle;
  FlightControlGains gains;
};

class SimAutopilot final : public Node {
 public:
  static constexpr Output<msg::VehicleState> kState{"state"};
  static constexpr Output<msg::NetFire> kFire{"fire"};

  static NodeSpec spec() {
    using C = SimAutopilotConfig;
    using G = FlightControlGains;
    ConfigSpec<C> c;
    mavlink::declare_connection(
        c, &C::connection, "the link, as PX4 SITL's: udpout://HOST:PORT, udpin://HOST:PORT or serial:///dev/PORT:BAUD");
    mavlink::declare_signing(c, &C::signing);
    c.param("rate_hz", &C::rate_hz).with_unit("Hz").range(20.0, 2000.0).describe("link polling and `state` rate");
    c.param("telemetry_hz", &C::telemetry_hz)
        .with_unit("Hz")
        .range(1.0, 500.0)
        .describe("LOCAL_POSITION_NED and ATTITUDE_QUATERNION rate (PX4's MAV_x streams)");
    c.param("control_hz", &C::control_hz).with_unit("Hz").range(50.0, 5000.0).describe("flight control loop rate");
    c.param("offboard_loss_timeout_s", &C::offboard_loss_timeout_s)
        .with_unit("s")
        .range(0.1, 60.0)
        .describe("COM_OF_LOSS_T: setpoints stopped this long in offboard drop the vehicle to hold");
    c.param("min_setpoint_rate_hz", &C::min_setpoint_rate_hz)
        .with_unit("Hz")
        .range(0.5, 100.0)
        .describe("offboard is granted only with setpoints streaming at least this fast");
    c.param("idle_speed_fraction", &C::idle_speed_fraction)
        .range(0.0, 0.5)
        .describe("armed on the ground outside offboard: rotors at this fraction of their top speed");
    c.choice("launcher", &C::launcher, {{"servo", C::Launcher::servo}, {"relay", C::Launcher::relay}})
        .describe("the output the net launcher hangs on: DO_SET_SERVO or DO_SET_RELAY");
    c.param("launcher_channel", &C::launcher_channel).range(0, 64).describe("its servo output or relay number");
    c.param("launcher_threshold", &C::launcher_threshold)
        .range(0.0, 3000.0)
        .describe("a servo PWM (us) or relay setting at or above which the launcher fires");
    vehicle::declare_simulation(c, &C::sim);
    vehicle::declare_multirotor(c, &C::vehicle);
    c.param("position_p", &C::gains, &G::position_p).with_unit("1/s").range(0.0, 100.0).describe("MPC_XY_P, MPC_Z_P");
    c.param("velocity_p", &C::gains, &G::velocity_p)
        .with_unit("1/s")
        .range(0.0, 100.0)
        .describe("MPC_XY_VEL_P_ACC, MPC_Z_VEL_P_ACC");
    c.param("velocity_i", &C::gains, &G::velocity_i)
        .with_unit("1/s^2")
        .range(0.0, 100.0)
        .describe("MPC_XY_VEL_I_ACC, MPC_Z_VEL_I_ACC");
    c.param("velocity_d", &C::gains, &G::velocity_d).range(0.0, 100.0).describe("MPC_XY_VEL_D_ACC, MPC_Z_VEL_D_ACC");
    c.param("max_speed_xy_m_s", &C::gains, &G::max_speed_xy_m_s)
        .with_unit("m/s")
        .range(0.1, 50.0)
        .describe("MPC_XY_VEL_MAX");
    c.param("max_speed_up_m_s", &C::gains, &G::max_speed_up_m_s)
        .with_unit("m/s")
        .range(0.1, 50.0)
        .describe("MPC_Z_VEL_MAX_UP");
    c.param("max_speed_down_m_s", &C::gains, &G::max_speed_down_m_s)
        .with_unit("m/s")
        .range(0.1, 50.0)
        .describe("MPC_Z_VEL_MAX_DN");
    c.param("max_tilt_deg", &C::gains, &G::max_tilt_deg).with_unit("deg").range(5.0, 85.0).describe("MPC_TILTMAX_AIR");
    c.param("attitude_p", &C::gains, &G::attitude_p)
        .with_unit("1/s")
        .range(0.0, 100.0)
        .describe("MC_ROLL_P, MC_PITCH_P, MC_YAW_P");
    c.param("max_rate_deg_s", &C::gains, &G::max_rate_deg_s)
        .with_unit("deg/s")
        .range(1.0, 2000.0)
        .describe("MC_ROLLRATE_MAX, MC_PITCHRATE_MAX, MC_YAWRATE_MAX");
    c.param("rate_p", &C::gains, &G::rate_p)
        .with_unit("1/s")
        .range(0.0, 1000.0)
        .describe("rate loop: angular acceleration per rad/s of rate error");
    c.param("rate_i", &C::gains, &G::rate_i).with_unit("1/s^2").range(0.0, 1000.0).describe("rate loop: integral gain");
    c.param("rate_d", &C::gains, &G::rate_d).range(0.0, 10.0).describe("rate loop: derivative gain");
    c.rule("integration_hz >= control_hz >= rate_hz", {"integration_hz", "control_hz", "rate_hz"},
           [](const C& k) { return k.sim.integration_hz >= k.control_hz && k.control_hz >= k.rate_hz; });
    return NodeSpec("sim_autopilot", "Simulated PX4 vehicle on a MAVLink link, for software-in-the-loop runs")
        .details(
            "Flies quadrotor_sim's multirotor with its own position, attitude and rate loops (PX4's cascade and "
            "defaults), on the setpoints a companion streams over `connection` (SET_POSITION_TARGET_LOCAL_NED or "
            "SET_ATTITUDE_TARGET, thrust 0..1 of the rotors' top thrust). It follows PX4's offboard rules: offboard "
            "only with a setpoint stream, hold when the stream stops for offboard_loss_timeout_s, no disarming in the "
            "air. Sends HEARTBEAT (1 Hz), LOCAL_POSITION_NED and ATTITUDE_QUATERNION (telemetry_hz), "
            "EXTENDED_SYS_STATE, STATUSTEXT and COMMAND_ACK. The launcher's servo or relay output publishes `fire`. "
            "With `signing` it signs what it sends and judges what it receives as PX4 and ArduPilot do.")
        .needs_executor(ExecutorNeed::realtime, "it talks over a real link")
        .output(kState, "true state at rate_hz (for a camera or net riding on the vehicle)")
        .output(kFire, "a fire order when the launcher's output is set")
        .config(std::move(c));
  }

  explicit SimAutopilot(NodeInit& init) : SimAutopilot(init, init.config<SimAutopilotConfig>()) {}

  void tick(Context& ctx) override {
    const double now = to_seconds(ctx.now());
    receive(ctx, now);
    rules_.step(now);
    for (const std::string& text : rules_.take_texts()) {
      ctx.log().info("t = {:.2f} s: {}", now, text);
      mavlink::StatusText t;
      t.set_text(text);
      send(t);
    }
    flight_.advance_to(now, [&](double t) {
      if (t + 1e-12 < next_control_s_) return;
      next_control_s_ += 1.0 / cfg_.control_hz;
      control();
    });
    if (now >= next_telemetry_s_) {
      next_telemetry_s_ = now + 1.0 / cfg_.telemetry_hz;
      send_telemetry(now);
    }
    if (now >= next_heartbeat_s_) {
      next_heartbeat_s_ = now + 1.0;
      send(rules_.heartbeat());
      mavlink::ExtendedSysState e;
      e.landed_state = flight_.on_ground() ? mav::landed_on_ground : mav::landed_in_air;
      send(e);
    }
    ctx.publish(kState, flight_.vehicle_state(ctx.now()));
  }

  void finish(Context& ctx) override {
    const OffboardRulesCounts& k = rules_.counts();
    const mavlink::ParserCounts& p = parser_.counts();
    const nlohmann::json rate =
        k.setpoints > 1 && last_setpoint_s_ > first_setpoint_s_
            ? nlohmann::json(static_cast<double>(k.setpoints - 1) / (last_setpoint_s_ - first_setpoint_s_))
            : nlohmann::json(nullptr);
    ReportSection section;
    mavlink::report_signing(section, cfg_.signing.mode, signing_ ? signing_->counts() : mavlink::SigningCounts{});
    vehicle::report_flight(
        ctx, flight_,
        section.info("connection", cfg_.connection)
            .info("mode", OffboardRules::mode_name(rules_.mode()))
            .info("armed", rules_.armed())
            .quantity("hover_thrust", hover_thrust())
            .quantity("setpoints", k.setpoints)
            .metric("setpoint_rate_hz", rate, "Hz", Better::higher)
            .quantity("offboard_grants", k.offboard_grants)
            .metric("offboard_refusals", k.offboard_refusals, "", Better::lower)
            .metric("offboard_losses", k.offboard_losses, "", Better::lower)
            .quantity("arms", k.arms)
            .quantity("disarms", k.disarms)
            .metric("refused_commands", k.refused_commands, "", Better::lower)
            .metric("unsupported_commands", k.unsupported_commands, "", Better::lower)
            .quantity("fire_orders", fire_orders_)
            .quantity("frames", p.frames)
            .metric("bad_checksum", p.bad_checksum, "", Better::lower)
            .metric("unknown_id", p.unknown_id, "", Better::lower)
            .quantity("companion_heartbeats", companion_heartbeats_)
            .quantity("frames_sent", frames_sent_)
            .metric("send_failures", send_failures_, "", Better::lower),
        fmt::format("Autopilot: {} setpoints received, offboard granted {} time(s), lost {} "
                    "time(s); {} fire order(s); {} bad checksum(s).\n",
                    k.setpoints, k.offboard_grants, k.offboard_losses, fire_orders_, p.bad_checksum));
  }

 private:
  SimAutopilot(NodeInit& init, const SimAutopilotConfig& cfg)
      : cfg_(cfg),
        flight_(cfg.vehicle.multirotor(), cfg.sim, init.seed()),
        control_(flight_.vehicle(), cfg.gains, cfg.sim.gravity_m_s2, flight_.max_thrust_n()),
        rules_(OffboardRulesOptions{cfg.offboard_loss_timeout_s, cfg.min_setpoint_rate_hz}),
        signing_(mavlink::make_signing(cfg.signing)),
        writer_({1, mav::comp_autopilot1}, signing_) {
    const auto rotors = static_cast<Eigen::Index>(flight_.vehicle().rotors.size());
    stopped_ = Eigen::VectorXd::Zero(rotors);
    idle_ = Eigen::VectorXd::Constant(rotors, cfg.idle_speed_fraction * flight_.vehicle().max_rotor_speed_rad_s);
    transport_ = mavlink::open_transport(mavlink::parse_connection_url(cfg.connection));
    init.set_rate(cfg.rate_hz);
  }

  double hover_thrust() const { return flight_.vehicle().mass_kg * cfg_.sim.gravity_m_s2 / flight_.max_thrust_n(); }

  template <class M>
  void send(const M& message) {
    if (transport_->send(writer_.encode(message)))
      ++frames_sent_;
    else
      ++send_failures_;  // nobody listens yet (udpout before the companion is up), or udpin before it spoke
  }

  // Everything that arrived since the last tick, without waiting.
  void receive(Context& ctx, double now) {
    for (int datagrams = 0; datagrams < 1000; ++datagrams) {
      const std::size_t n = transport_->receive(buffer_, std::chrono::milliseconds(0));
      if (n == 0) return;
      for (const mavlink::Frame& frame : parser_.feed(std::span(buffer_.data(), n)))
        if (!signing_ || signing_->admit(frame)) take(ctx, frame, now);
    }
  }

  void take(Context& ctx, const mavlink::Frame& frame, double now) {
    if (frame.is<mavlink::Heartbeat>()) ++companion_heartbeats_;
    const std::uint64_t before = rules_.counts().setpoints;
    const OffboardRules::Response r = rules_.on_frame(frame, now, flight_.on_ground());
    if (rules_.counts().setpoints > before) {  // a setpoint for this vehicle: its stream's span
      if (before == 0) first_setpoint_s_ = now;
      last_setpoint_s_ = now;
    }
    if (r.ack) send(*r.ack);
    if (r.output && r.output->relay == (cfg_.launcher == SimAutopilotConfig::Launcher::relay) &&
        r.output->channel == cfg_.launcher_channel && r.output->value >= cfg_.launcher_threshold) {
      ++fire_orders_;
      ctx.log().info("t = {:.2f} s: launcher output {} set to {:g}: fire", now, r.output->channel, r.output->value);
      msg::NetFire fire;
      fire.stamp = ctx.now();
      ctx.publish(kFire, std::move(fire));
    }
  }

  // One step of flight control, at control_hz in simulated time.
  void control() {
    const vehicle::RigidBodyState& s = flight_.state();
    const double dt = 1.0 / cfg_.control_hz;
    if (!rules_.armed()) {
      flight_.command_rotor_speeds(stopped_);
      control_.reset();
      hold_.reset();
      return;
    }
    BodyWrench wrench;
    if (const auto sp = rules_.setpoint()) {
      hold_.reset();
      if (const auto* p = std::get_if<mavlink::SetPositionTargetLocalNed>(&sp->target))
        wrench = control_.position(position_target(*p), s, dt);
      else
        wrench = control_.attitude(attitude_command(std::get<mavlink::SetAttitudeTarget>(sp->target)), s, dt);
    } else if (flight_.on_ground()) {
      flight_.command_rotor_speeds(idle_);  // armed, waiting: the props spin at idle
      control_.reset();
      return;
    } else {
      if (!hold_) {  // hold where the vehicle is, heading kept (PX4's Hold)
        hold_ = PositionTarget{};
        hold_->position = s.position;
        hold_->velocity = Eigen::Vector3d::Zero();
        hold_->yaw = geometry::yaw_of(s.orientation);
      }
      wrench = control_.position(*hold_, s, dt);
    }
    if (flight_.on_ground()) control_.reset();  // PX4 keeps its integrators still while landed
    flight_.command_wrench(wrench.thrust_n, wrench.torque_nm);
  }

  // POSITION_TARGET_TYPEMASK: a set bit ignores that part; an axis of a part ignored ignores the part.
  static PositionTarget position_target(const mavlink::SetPositionTargetLocalNed& t) {
    PositionTarget out;
    const auto used = [&](std::uint16_t bits) { return (t.type_mask & bits) == 0; };
    if (used(1 | 2 | 4)) out.position = geometry::ned_to_enu(Eigen::Vector3d(t.x, t.y, t.z));
    if (used(8 | 16 | 32)) out.velocity = geometry::ned_to_enu(Eigen::Vector3d(t.vx, t.vy, t.vz));
    if (used(64 | 128 | 256)) out.acceleration = geometry::ned_to_enu(Eigen::Vector3d(t.afx, t.afy, t.afz));
    if (used(1024)) out.yaw = geometry::yaw_ned_to_enu(t.yaw);
    return out;
  }

  // ATTITUDE_TARGET_TYPEMASK: 1, 2, 4 ignore a body rate, 64 the throttle, 128 the attitude.
  AttitudeCommand attitude_command(const mavlink::SetAttitudeTarget& t) const {
    AttitudeCommand out;
    if ((t.type_mask & 128) == 0) {
      const Eigen::Quaterniond q(t.q[0], t.q[1], t.q[2], t.q[3]);
      if (q.coeffs().allFinite() && q.norm() > 0.5) out.orientation = geometry::ned_frd_to_enu_flu(q.normalized());
    }
    Eigen::Vector3d rates = geometry::frd_to_flu(Eigen::Vector3d(t.body_roll_rate, t.body_pitch_rate, t.body_yaw_rate));
    for (int i = 0; i < 3; ++i)
      if ((t.type_mask & (1 << i)) != 0 || !std::isfinite(rates(i))) rates(i) = 0.0;
    out.body_rates = rates;
    const double thrust = (t.type_mask & 64) != 0 || !std::isfinite(t.thrust) ? hover_thrust() : t.thrust;
    out.thrust_n = std::clamp(thrust, 0.0, 1.0) * flight_.max_thrust_n();
    return out;
  }

  void send_telemetry(double now) {
    const vehicle::RigidBodyState& s = flight_.state();
    const auto boot_ms = static_cast<std::uint32_t>(now * 1000.0);
    mavlink::LocalPositionNed p;
    p.time_boot_ms = boot_ms;
    const Eigen::Vector3d position = geometry::enu_to_ned(s.position), velocity = geometry::enu_to_ned(s.velocity);
    p.x = static_cast<float>(position.x());
    p.y = static_cast<float>(position.y());
    p.z = static_cast<float>(position.z());
    p.vx = static_cast<float>(velocity.x());
    p.vy = static_cast<float>(velocity.y());
    p.vz = static_cast<float>(velocity.z());
    send(p);
    mavlink::AttitudeQuaternion a;
    a.time_boot_ms = boot_ms;
    const Eigen::Quaterniond q = geometry::enu_flu_to_ned_frd(s.orientation);
    a.q1 = static_cast<float>(q.w());
    a.q2 = static_cast<float>(q.x());
    a.q3 = static_cast<float>(q.y());
    a.q4 = static_cast<float>(q.z());
    const Eigen::Vector3d rates = geometry::flu_to_frd(s.angular_velocity);
    a.rollspeed = static_cast<float>(rates.x());
    a.pitchspeed = static_cast<float>(rates.y());
    a.yawspeed = static_cast<float>(rates.z());
    send(a);
  }

  SimAutopilotConfig cfg_;
  vehicle::SimulatedMultirotor flight_;
  FlightControl control_;
  OffboardRules rules_;
  std::shared_ptr<mavlink::Signing> signing_;  // nullptr: signing off
  mavlink::FrameWriter writer_;
  mavlink::FrameParser parser_;
  std::unique_ptr<mavlink::Transport> transport_;
  std::vector<std::uint8_t> buffer_ = std::vector<std::uint8_t>(65536);
  std::optional<PositionTarget> hold_;
  Eigen::VectorXd stopped_, idle_;  // rotor speeds disarmed, and armed on the ground
  double next_control_s_ = 0.0, next_telemetry_s_ = 0.0, next_heartbeat_s_ = 0.0;
  double first_setpoint_s_ = 0.0, last_setpoint_s_ = 0.0;
  std::uint64_t companion_heartbeats_ = 0, fire_orders_ = 0, frames_sent_ = 0, send_failures_ = 0;
};
KESTREL_REGISTER_NODE(SimAutopilot)

}  // namespace kestrel::sim_autopilot
