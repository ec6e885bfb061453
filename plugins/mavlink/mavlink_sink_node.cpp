// The `mavlink_sink` node: flies the vehicle through its autopilot. It streams the planner's
// position setpoints (SET_POSITION_TARGET_LOCAL_NED) or the Lee controller's attitude and thrust
// (SET_ATTITUDE_TARGET) at a steady rate, sends a heartbeat as the onboard controller at 1 Hz,
// pre-streams before it asks for offboard (PX4) or GUIDED (ArduPilot), arms only when told to,
// and fires the net through a servo or relay command. Whatever arrives from upstream, what it
// sends is finite and inside the fence and the limits (SetpointGuard); a stale or refused command
// becomes a hold at the vehicle's position; a lost heartbeat stops the commanding until the
// autopilot is back (OffboardSession). docs/field.md.
#include <fmt/format.h>

#include <kestrel/geometry/frames.hpp>
#include <kestrel/geometry/ned_enu.hpp>
#include <kestrel/messages/attitude_target.hpp>
#include <kestrel/messages/net_fire.hpp>
#include <kestrel/messages/trajectory_setpoint.hpp>
#include <kestrel/plugin.hpp>
#include <numbers>

#include "kestrel/mavlink/connection_param.hpp"
#include "link.hpp"
#include "link_options_param.hpp"
#include "link_status.hpp"
#include "offboard_session.hpp"
#include "setpoint_guard.hpp"
#include "vehicle_state_conversion.hpp"

namespace kestrel::mavlink {

namespace {

// POSITION_TARGET_TYPEMASK: position, velocity, acceleration (as feed-forward, not force) and yaw
// are used; the yaw rate is ignored.
constexpr std::uint16_t kPositionVelocityAccelerationYaw = 2048;

}  // namespace

struct MavlinkSinkConfig {
  enum class Command { position, attitude };
  enum class FireCommand { servo, relay };
  std::string connection = "udpin://0.0.0.0:14540";
  Command command = Command::position;
  double rate_hz = 50.0;
  double prestream_s = 1.0;
  bool arm = false;
  bool net_armed = false;
  FireCommand fire_command = FireCommand::servo;
  std::int64_t fire_channel = 9;
  double fire_value = 1900.0;
  double hover_thrust = 0.5;
  double command_timeout_s = 0.5;
  double heartbeat_timeout_s = 1.5;
  PeerConfig peer;
  SigningConfig signing;
  double connect_timeout_s = 10.0;
  double ack_timeout_s = 1.0;
  std::int64_t retries = 3;
  Eigen::Vector3d fence_min_m{-50.0, -50.0, 0.5};
  Eigen::Vector3d fence_max_m{50.0, 50.0, 30.0};
  double max_speed_m_s = 8.0;
  double max_tilt_deg = 35.0;
};

class MavlinkSink final : public Node {
 public:
  static constexpr Input<msg::TrajectorySetpoint> kSetpoint{"setpoint"};
  static constexpr Input<msg::AttitudeTarget> kAttitude{"attitude"};
  static constexpr Input<msg::NetFire> kFire{"fire"};

  static NodeSpec spec() {
    using C = MavlinkSinkConfig;
    ConfigSpec<C> c;
    declare_connection(c, &C::connection,
                       "the link: udpin://HOST:PORT, udpout://HOST:PORT or serial:///dev/PORT:BAUD (MAVSDK's forms)");
    c.choice("command", &C::command, {{"position", C::Command::position}, {"attitude", C::Command::attitude}})
        .describe("what is flown: the setpoint input as position targets, or the attitude input");
    c.param("rate_hz", &C::rate_hz)
        .with_unit("Hz")
        .range(20.0, 500.0)
        .describe("setpoint stream rate (PX4 leaves offboard below 2 Hz)");
    c.param("prestream_s", &C::prestream_s)
        .with_unit("s")
        .range(1.0, 30.0)
        .describe("setpoints streamed before the mode is asked for");
    c.param("arm", &C::arm).describe("arm the vehicle (COMPONENT_ARM_DISARM) after the pre-stream");
    c.param("net_armed", &C::net_armed).describe("let a fire order through to the launcher");
    c.choice("fire_command", &C::fire_command, {{"servo", C::FireCommand::servo}, {"relay", C::FireCommand::relay}})
        .describe("how the launcher is triggered: MAV_CMD_DO_SET_SERVO or MAV_CMD_DO_SET_RELAY");
    c.param("fire_channel", &C::fire_channel).range(0, 64).describe("servo output or relay number of the launcher");
    c.param("fire_value", &C::fire_value)
        .range(0.0, 3000.0)
        .describe("servo PWM in microseconds, or the relay setting (1 on)");
    c.param("hover_thrust", &C::hover_thrust)
        .range(0.05, 0.95)
        .describe("normalised thrust (0..1) at which the vehicle hovers, for attitude commands");
    c.param("command_timeout_s", &C::command_timeout_s)
        .with_unit("s")
        .range(0.02, 10.0)
        .describe("an upstream command older than this is stale: the vehicle holds its position");
    c.param("heartbeat_timeout_s", &C::heartbeat_timeout_s)
        .with_unit("s")
        .range(0.1, 60.0)
        .describe("the autopilot is lost when its last heartbeat is older: commanding stops");
    declare_peer(c, &C::peer, &C::signing);
    c.param("connect_timeout_s", &C::connect_timeout_s)
        .with_unit("s")
        .range(0.1, 600.0)
        .describe("no heartbeat at all by then stops the run with an error");
    c.param("ack_timeout_s", &C::ack_timeout_s).with_unit("s").range(0.05, 30.0).describe("wait for a COMMAND_ACK");
    c.param("retries", &C::retries).range(0, 20).describe("re-sends of a command that had no answer");
    c.param("fence_min_m", &C::fence_min_m).with_unit("m").describe("geofence box, lower corner (world ENU)");
    c.param("fence_max_m", &C::fence_max_m).with_unit("m").describe("geofence box, upper corner (world ENU)");
    c.param("max_speed_m_s", &C::max_speed_m_s).with_unit("m/s").range(0.1, 50.0).describe("speed limit");
    c.param("max_tilt_deg", &C::max_tilt_deg).with_unit("deg").range(5.0, 80.0).describe("tilt limit");
    c.rule("fence_min_m < fence_max_m", {"fence_min_m", "fence_max_m"},
           [](const C& config) { return (config.fence_min_m.array() < config.fence_max_m.array()).all(); });
    return NodeSpec("mavlink_sink", "Flies the vehicle through its autopilot over MAVLink (offboard / GUIDED)")
        .details(
            "Streams position or attitude setpoints at rate_hz, converted to NED/FRD, with a heartbeat at 1 Hz as the "
            "onboard controller; pre-streams, arms when `arm` is true, then asks for offboard (PX4) or GUIDED "
            "(ArduPilot) and retries unanswered commands. Non-finite commands are refused, positions clamped to the "
            "fence, speeds and tilts to their limits; stale commands become a hold at the vehicle's position; a lost "
            "heartbeat stops the commanding until the autopilot returns, through the pre-stream again. A fire order "
            "goes out only when armed, in the mode and net_armed. Every refusal and failsafe is counted in the report.")
        .needs_executor(ExecutorNeed::realtime, "it talks to a real link")
        .input(kSetpoint, "the planner's setpoints (world ENU)", {.trigger = Trigger::latest, .optional = true})
        .input(kAttitude, "the controller's attitude and thrust", {.trigger = Trigger::latest, .optional = true})
        .input(kFire, "fire orders", {.trigger = Trigger::on_message, .optional = true})
        .config(std::move(c));
  }

  explicit MavlinkSink(NodeInit& init)
      : cfg_(init.config<MavlinkSinkConfig>()),
        guard_(GuardLimits{cfg_.fence_min_m, cfg_.fence_max_m, cfg_.max_speed_m_s, cfg_.max_tilt_deg}),
        session_(SessionOptions{cfg_.prestream_s, cfg_.arm, cfg_.ack_timeout_s, static_cast<int>(cfg_.retries)}) {
    link_ = Link::open(cfg_.connection, link_options(cfg_.peer, cfg_.signing, cfg_.heartbeat_timeout_s));
    init.set_rate(cfg_.rate_hz);
  }

  void tick(Context& ctx) override {
    if (const auto failure = link_->failure()) throw Error("the link failed: " + *failure);
    const double now_s = to_seconds(ctx.now());
    const VehicleView view = link_->view();
    const AutopilotState autopilot = autopilot_state(view);
    if (view.heartbeat_count == 0 && now_s > cfg_.connect_timeout_s)
      throw Error(
          fmt::format("no heartbeat from the autopilot on {} in {:g} s", cfg_.connection, cfg_.connect_timeout_s));
    if (now_s >= next_heartbeat_s_) {
      next_heartbeat_s_ = now_s + 1.0;
      Heartbeat hb;
      hb.type = mav::type_onboard_controller;
      hb.autopilot = mav::autopilot_invalid;
      hb.system_status = mav::state_active;
      link_->send(hb);
    }
    for (const CommandAck& ack : link_->take_acks()) session_.on_ack(ack);
    for (const StatusText& text : link_->take_texts()) ctx.log().info("autopilot: {}", text.text_string());

    const auto before = session_.phase();
    session_.step(now_s, autopilot);
    if (session_.phase() != before) {
      ctx.log().info("t = {:.2f} s: {}{}", now_s, session_.phase_name(),
                     session_.phase() == OffboardSession::Phase::refused ? " (" + session_.refusal() + ")" : "");
    }
    if (const auto command = session_.command_due(now_s)) link_->send(*command);
    if (!session_.streaming()) return;
    if (!streaming_since_s_) streaming_since_s_ = now_s;
    stream(ctx, view);
  }

  void process(Context& ctx) override {
    const auto fire = ctx.get(kFire);
    if (!fire) return;
    const AutopilotState autopilot = autopilot_state(link_->view());
    if (!cfg_.net_armed || !session_.flying(autopilot)) {
      ++fire_refused_;
      ctx.log().warn("fire order for target {} not sent: {}", fire->target_id,
                     !cfg_.net_armed ? "net_armed is false" : "the vehicle is not armed and in offboard/GUIDED");
      return;
    }
    CommandLong c;
    c.target_system = autopilot.system_id;
    c.target_component = autopilot.component_id;
    const bool relay = cfg_.fire_command == MavlinkSinkConfig::FireCommand::relay;
    c.command = relay ? mav::cmd_do_set_relay : mav::cmd_do_set_servo;
    c.param1 = static_cast<float>(cfg_.fire_channel);
    c.param2 = static_cast<float>(cfg_.fire_value);
    link_->send(c);
    ++fired_;
    ctx.log().info("fire: {} {} = {}", relay ? "relay" : "servo", cfg_.fire_channel, cfg_.fire_value);
  }

  void finish(Context& ctx) override {
    const GuardCounts& g = guard_.counts();
    const SessionCounts& s = session_.counts();
    const CommandCounts& k = session_.command_counts();
    const double streamed_s = streaming_since_s_ ? last_sent_s_ - *streaming_since_s_ : 0.0;
    const double rate = streamed_s > 0 ? static_cast<double>(setpoints_ - 1) / streamed_s : 0.0;
    ReportSection section;
    report_link_guard(section, link_->view());
    ctx.set_report_section(
        ctx.id(),
        section.info("connection", cfg_.connection)
            .info("phase", session_.phase_name())
            .info("refusal", session_.refusal())
            .quantity("setpoints", setpoints_)
            .metric("setpoint_rate_hz", setpoints_ > 1 ? nlohmann::json(rate) : nlohmann::json(nullptr), "Hz",
                    Better::higher)
            .metric("holds", holds_, "", Better::lower)
            .quantity("hold_setpoints", hold_setpoints_)
            .metric("non_finite", g.non_finite, "", Better::lower)
            .metric("fence_clamps", g.fence_clamps, "", Better::lower)
            .metric("speed_clamps", g.speed_clamps, "", Better::lower)
            .metric("tilt_clamps", g.tilt_clamps, "", Better::lower)
            .metric("thrust_clamps", g.thrust_clamps, "", Better::lower)
            .metric("link_losses", s.link_losses, "", Better::lower)
            .metric("releases", s.releases, "", Better::lower)
            .metric("refusals", s.refusals, "", Better::lower)
            .metric("temporary_rejections", s.temporary_rejections, "", Better::lower)
            .quantity("arm_requests", s.arm_requests)
            .quantity("control_requests", s.control_requests)
            .metric("commands_resent", k.resent, "", Better::lower)
            .quantity("fired", fired_)
            .metric("fire_refused", fire_refused_, "", Better::lower)
            .markdown(fmt::format(
                "{} setpoints at {:.1f} Hz, phase '{}'; {} hold(s), {} non-finite refused, {} link loss(es), "
                "{} fire order(s) sent, {} refused.\n",
                setpoints_, rate, session_.phase_name(), holds_, g.non_finite, s.link_losses, fired_, fire_refused_)));
  }

 private:
  AutopilotState autopilot_state(const VehicleView& view) const {
    AutopilotState a;
    a.link_up = link_up(view, LinkClock::now(), cfg_.heartbeat_timeout_s);
    a.kind = autopilot_kind(view.heartbeat.autopilot);
    a.armed = view.heartbeat_count > 0 && is_armed(view.heartbeat);
    a.external_control = view.heartbeat_count > 0 && in_external_control(a.kind, view.heartbeat);
    a.system_id = view.system_id;
    a.component_id = view.component_id;
    return a;
  }

  // The vehicle's position and heading now, from what the autopilot reports.
  std::optional<msg::TrajectorySetpoint> current_pose(const VehicleView& view) const {
    std::optional<msg::VehicleState> state;
    if (view.odometry_count > 0) state = vehicle_state(view.odometry);
    if (!state && view.position_count > 0 && view.attitude_count > 0)
      state = vehicle_state(view.position, view.attitude);
    if (!state) return std::nullopt;
    msg::TrajectorySetpoint hold;
    hold.position = state->position;
    hold.yaw = geometry::yaw_of(state->orientation);
    return hold;
  }

  template <class M>
  std::shared_ptr<const M> fresh(Context& ctx, const Input<M>& port) const {
    auto m = ctx.get(port);
    if (!m || to_seconds(ctx.now()) - to_seconds(m->stamp) > cfg_.command_timeout_s) return nullptr;
    return m;
  }

  void stream(Context& ctx, const VehicleView& view) {
    const std::uint8_t target_system = view.system_id, target_component = view.component_id;
    if (cfg_.command == MavlinkSinkConfig::Command::attitude) {
      if (const auto a = fresh(ctx, kAttitude)) {
        if (const auto safe = guard_.attitude(*a)) {
          SetAttitudeTarget t;
          t.target_system = target_system;
          t.target_component = target_component;
          const Eigen::Quaterniond q = geometry::enu_flu_to_ned_frd(safe->orientation);
          t.q = {static_cast<float>(q.w()), static_cast<float>(q.x()), static_cast<float>(q.y()),
                 static_cast<float>(q.z())};
          const Eigen::Vector3d rates = geometry::flu_to_frd(safe->body_rates);
          t.body_roll_rate = static_cast<float>(rates.x());
          t.body_pitch_rate = static_cast<float>(rates.y());
          t.body_yaw_rate = static_cast<float>(rates.z());
          t.thrust = static_cast<float>(guard_.normalised_thrust(*safe, cfg_.hover_thrust));
          t.time_boot_ms = static_cast<std::uint32_t>(to_seconds(ctx.now()) * 1000.0);
          sent(ctx, link_->send(t), false);
          return;
        }
      }
    } else if (const auto sp = fresh(ctx, kSetpoint)) {
      if (const auto safe = guard_.position(*sp)) {
        send_position(ctx, *safe, target_system, target_component, false);
        return;
      }
    }
    // Nothing fresh and safe: hold where the vehicle was when the commands stopped.
    if (!hold_) {
      hold_ = current_pose(view);
      if (!hold_) return;  // nothing known of the vehicle yet: nothing safe to send
      ++holds_;
    }
    send_position(ctx, *guard_.position(*hold_), target_system, target_component, true);
  }

  void send_position(Context& ctx, const msg::TrajectorySetpoint& sp, std::uint8_t system, std::uint8_t component,
                     bool holding) {
    SetPositionTargetLocalNed t;
    t.target_system = system;
    t.target_component = component;
    t.coordinate_frame = mav::frame_local_ned;
    t.type_mask = kPositionVelocityAccelerationYaw;
    const Eigen::Vector3d p = geometry::enu_to_ned(sp.position), v = geometry::enu_to_ned(sp.velocity),
                          a = geometry::enu_to_ned(sp.acceleration);
    t.x = static_cast<float>(p.x());
    t.y = static_cast<float>(p.y());
    t.z = static_cast<float>(p.z());
    t.vx = static_cast<float>(v.x());
    t.vy = static_cast<float>(v.y());
    t.vz = static_cast<float>(v.z());
    t.afx = static_cast<float>(a.x());
    t.afy = static_cast<float>(a.y());
    t.afz = static_cast<float>(a.z());
    t.yaw = static_cast<float>(geometry::yaw_enu_to_ned(sp.yaw));
    t.time_boot_ms = static_cast<std::uint32_t>(to_seconds(ctx.now()) * 1000.0);
    sent(ctx, link_->send(t), holding);
  }

  void sent(Context& ctx, bool ok, bool holding) {
    if (!ok) return;
    ++setpoints_;
    if (holding) {
      ++hold_setpoints_;
    } else {
      hold_.reset();
    }
    last_sent_s_ = to_seconds(ctx.now());
  }

  MavlinkSinkConfig cfg_;
  SetpointGuard guard_;
  OffboardSession session_;
  std::shared_ptr<Link> link_;
  std::optional<msg::TrajectorySetpoint> hold_;
  std::optional<double> streaming_since_s_;
  double next_heartbeat_s_ = 0.0, last_sent_s_ = 0.0;
  std::uint64_t setpoints_ = 0, holds_ = 0, hold_setpoints_ = 0, fired_ = 0, fire_refused_ = 0;
};
KESTREL_REGISTER_NODE(MavlinkSink)

}  // namespace kestrel::mavlink
