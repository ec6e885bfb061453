// The `mavlink_source` node: the vehicle as its autopilot reports it over MAVLink, in kestrel's
// frames. LOCAL_POSITION_NED with ATTITUDE_QUATERNION, or ODOMETRY, becomes a VehicleState (ENU
// world, FLU body); the heartbeat and EXTENDED_SYS_STATE become an AutopilotStatus (armed, mode,
// link health). It shares its link with a `mavlink_sink` of the same URL (docs/field.md).
#include <fmt/format.h>

#include <kestrel/plugin.hpp>

#include "kestrel/mavlink/connection_param.hpp"
#include "link.hpp"
#include "link_options_param.hpp"
#include "link_status.hpp"
#include "vehicle_state_conversion.hpp"

namespace kestrel::mavlink {

struct MavlinkSourceConfig {
  std::string connection = "udpin://0.0.0.0:14540";
  enum class StateFrom { automatic, local_position, odometry };
  StateFrom state_from = StateFrom::automatic;
  double rate_hz = 100.0;
  double status_rate_hz = 5.0;
  double heartbeat_timeout_s = 1.5;
  PeerConfig peer;
  SigningConfig signing;
};

class MavlinkSource final : public Node {
 public:
  static constexpr Output<msg::VehicleState> kState{"state"};
  static constexpr Output<msg::AutopilotStatus> kStatus{"status"};

  static NodeSpec spec() {
    using C = MavlinkSourceConfig;
    ConfigSpec<C> c;
    declare_connection(c, &C::connection,
                       "the link: udpin://HOST:PORT, udpout://HOST:PORT or serial:///dev/PORT:BAUD (MAVSDK's forms)");
    c.choice("state_from", &C::state_from,
             {{"auto", C::StateFrom::automatic},
              {"local_position", C::StateFrom::local_position},
              {"odometry", C::StateFrom::odometry}})
        .describe(
            "LOCAL_POSITION_NED with ATTITUDE_QUATERNION, or ODOMETRY; auto takes ODOMETRY once it arrives, the pair "
            "until then");
    c.param("rate_hz", &C::rate_hz).with_unit("Hz").range(1.0, 1000.0).describe("how often the link is read");
    c.param("status_rate_hz", &C::status_rate_hz)
        .with_unit("Hz")
        .range(0.1, 100.0)
        .describe("how often the autopilot's status is published");
    c.param("heartbeat_timeout_s", &C::heartbeat_timeout_s)
        .with_unit("s")
        .range(0.1, 60.0)
        .describe("the link is down when the autopilot's last heartbeat is older");
    declare_peer(c, &C::peer, &C::signing);
    return NodeSpec("mavlink_source", "The vehicle's state and status from its autopilot over MAVLink")
        .details(
            "Publishes a VehicleState for each new position or odometry message, converted from NED/FRD to kestrel's "
            "ENU/FLU, and the autopilot's status (armed, flight mode, link health). Reports frames, refusals and link "
            "losses.")
        .needs_executor(ExecutorNeed::realtime, "it talks to a real link")
        .output(kState, "the vehicle's state (world ENU, body FLU)")
        .output(kStatus, "the autopilot's armed state, mode and link health")
        .config(std::move(c));
  }

  explicit MavlinkSource(NodeInit& init) : cfg_(init.config<MavlinkSourceConfig>()) {
    link_ = Link::open(cfg_.connection, link_options(cfg_.peer, cfg_.signing, cfg_.heartbeat_timeout_s));
    init.set_rate(cfg_.rate_hz);
  }

  void tick(Context& ctx) override {
    if (const auto failure = link_->failure()) throw Error("the link failed: " + *failure);
    const VehicleView view = link_->view();
    const auto now = LinkClock::now();
    publish_state(ctx, view);
    const bool up = link_up(view, now, cfg_.heartbeat_timeout_s);
    if (was_up_ && !up) ++link_losses_;
    was_up_ = up;
    if (to_seconds(ctx.now()) >= next_status_s_) {
      next_status_s_ = to_seconds(ctx.now()) + 1.0 / cfg_.status_rate_hz;
      msg::AutopilotStatus status = autopilot_status(view, now, cfg_.heartbeat_timeout_s);
      status.stamp = ctx.now();
      last_status_ = status;
      ctx.publish(kStatus, std::move(status));
    }
    last_view_ = view;
  }

  void finish(Context& ctx) override {
    const auto& p = last_view_.parser;
    ReportSection section;
    report_link_guard(section, link_->view());
    ctx.set_report_section(
        ctx.id(),
        section.info("connection", cfg_.connection)
            .quantity("frames", p.frames)
            .metric("bad_checksum", p.bad_checksum, "frames", Better::lower)
            .metric("unknown_id", p.unknown_id, "frames", Better::lower)
            .metric("bad_flags", p.bad_flags, "frames", Better::lower)
            .quantity("heartbeats", last_view_.heartbeat_count)
            .quantity("states", states_)
            .metric("link_losses", link_losses_, "", Better::lower)
            .info("autopilot", last_status_.autopilot)
            .info("mode", last_status_.mode)
            .info("armed", last_status_.armed)
            .markdown(fmt::format("{} frames from {} ({} bad checksums), {} heartbeats, {} states, {} link "
                                  "loss(es); last mode '{}'{}.\n",
                                  p.frames, cfg_.connection, p.bad_checksum, last_view_.heartbeat_count, states_,
                                  link_losses_, last_status_.mode, last_status_.armed ? ", armed" : "")));
  }

 private:
  void publish_state(Context& ctx, const VehicleView& view) {
    using From = MavlinkSourceConfig::StateFrom;
    const bool use_odometry =
        cfg_.state_from == From::odometry || (cfg_.state_from == From::automatic && view.odometry_count > 0);
    std::optional<msg::VehicleState> state;
    if (use_odometry) {
      if (view.odometry_count != last_view_.odometry_count) state = vehicle_state(view.odometry);
    } else if (view.position_count > 0 && view.attitude_count > 0 &&
               (view.position_count != last_view_.position_count || view.attitude_count != last_view_.attitude_count)) {
      state = vehicle_state(view.position, view.attitude);
    }
    if (!state) return;
    state->stamp = ctx.now();
    ++states_;
    ctx.publish(kState, std::move(*state));
  }

  MavlinkSourceConfig cfg_;
  std::shared_ptr<Link> link_;
  VehicleView last_view_;
  msg::AutopilotStatus last_status_;
  bool was_up_ = false;
  double next_status_s_ = 0.0;
  std::uint64_t states_ = 0, link_losses_ = 0;
};
KESTREL_REGISTER_NODE(MavlinkSource)

}  // namespace kestrel::mavlink
