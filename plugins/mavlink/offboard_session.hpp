#pragma once
// The sink's dealings with the autopilot, as the PX4 offboard and ArduPilot guided-mode guides
// lay them out: wait for the autopilot's heartbeat; stream setpoints for the pre-stream time (PX4
// refuses offboard without a stream); arm, only when the graph says so; ask for the external-
// control mode; then fly. A heartbeat lost longer than the timeout stops the commanding and, when
// it comes back, starts again from the pre-stream. If the autopilot leaves the mode itself (the
// pilot's switch, its own failsafe) the session does not ask again: the pilot's choice stands.
// A request the autopilot rejects only for now (MAV_RESULT_TEMPORARILY_REJECTED: PX4 when the
// stream it saw is a little short of its second) streams on for another pre-stream and asks
// again, up to `retries` times; any other refusal is final.
#include <cstdint>
#include <optional>
#include <string>

#include "command_exchange.hpp"
#include "kestrel/mavlink/autopilot_modes.hpp"

namespace kestrel::mavlink {

struct SessionOptions {
  double prestream_s = 1.0;
  bool arm = false;
  double ack_timeout_s = 1.0;
  int retries = 3;
};

/// What the link says this cycle.
struct AutopilotState {
  bool link_up = false;
  bool armed = false;
  bool external_control = false;
  AutopilotKind kind = AutopilotKind::generic;
  std::uint8_t system_id = 1;
  std::uint8_t component_id = 1;
};

struct SessionCounts {
  std::uint64_t link_losses = 0;  ///< heartbeat lost longer than the timeout
  std::uint64_t control_requests = 0;
  std::uint64_t arm_requests = 0;
  std::uint64_t refusals = 0;              ///< an arm or mode request refused or unanswered, not asked again
  std::uint64_t temporary_rejections = 0;  ///< asked again after a pre-stream
  std::uint64_t releases = 0;              ///< the autopilot left the mode while engaged
};

class OffboardSession {
 public:
  enum class Phase {
    waiting_for_autopilot,
    prestreaming,
    arming,
    requesting_control,
    engaged,
    released,
    refused,
    link_lost
  };

  explicit OffboardSession(SessionOptions options)
      : options_(options), exchange_(options.ack_timeout_s, options.retries) {}

  /// Advances with this cycle's view of the autopilot.
  void step(double now_s, const AutopilotState& autopilot);
  void on_ack(const CommandAck& ack) { exchange_.on_ack(ack); }
  /// The command to send this cycle (an arm or mode request, or a retry of one).
  std::optional<CommandLong> command_due(double now_s) { return exchange_.due(now_s); }

  /// Whether setpoints go out this cycle: from the pre-stream on, not while the link is lost.
  bool streaming() const;
  /// Whether the vehicle is flying our setpoints: engaged, armed and in the mode.
  bool flying(const AutopilotState& autopilot) const {
    return phase_ == Phase::engaged && autopilot.armed && autopilot.external_control;
  }
  Phase phase() const { return phase_; }
  const char* phase_name() const;
  /// Why the session stopped asking (refused): the request and its result.
  const std::string& refusal() const { return refusal_; }
  const SessionCounts& counts() const { return counts_; }
  const CommandCounts& command_counts() const { return exchange_.counts(); }

 private:
  void request_control(double now_s, const AutopilotState& autopilot);
  void give_up(std::string why);
  /// After a refusal of the arm or mode request: asks again later or gives up.
  void refused(double now_s);

  SessionOptions options_;
  CommandExchange exchange_;
  Phase phase_ = Phase::waiting_for_autopilot;
  double phase_since_s_ = 0.0;
  std::string refusal_;
  SessionCounts counts_;
  int asked_again_ = 0;
};

}  // namespace kestrel::mavlink
