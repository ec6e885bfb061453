#pragma once
// One COMMAND_LONG at a time, as MAVLink's command protocol has it: sent, sent again (confirmation
// counting up) when no COMMAND_ACK came within the timeout, until the retries run out. An ACK of
// IN_PROGRESS keeps waiting; ACCEPTED ends it well, any other result ends it refused. Times are
// seconds on the caller's clock.
#include <cstdint>
#include <optional>

#include "kestrel/mavlink/messages.hpp"

namespace kestrel::mavlink {

struct CommandCounts {
  std::uint64_t sent = 0;    ///< first sends
  std::uint64_t resent = 0;  ///< sends after a timeout
  std::uint64_t accepted = 0;
  std::uint64_t refused = 0;    ///< an ACK other than ACCEPTED or IN_PROGRESS
  std::uint64_t timed_out = 0;  ///< no ACK after every retry
};

class CommandExchange {
 public:
  enum class State { idle, waiting, accepted, refused, timed_out };

  CommandExchange(double ack_timeout_s, int retries) : timeout_s_(ack_timeout_s), retries_(retries) {}

  /// Starts a command; any command still waiting is dropped.
  void start(const CommandLong& command, double now_s);
  /// The command to send now (the first send, or a retry), if any; call it every cycle.
  std::optional<CommandLong> due(double now_s);
  /// An ACK from the autopilot; ACKs for other commands are ignored.
  void on_ack(const CommandAck& ack);
  /// Back to idle after a result has been read.
  void reset() { state_ = State::idle; }

  State state() const { return state_; }
  std::uint16_t command() const { return command_.command; }
  std::uint8_t last_result() const { return last_result_; }
  const CommandCounts& counts() const { return counts_; }

 private:
  double timeout_s_;
  int retries_;
  State state_ = State::idle;
  CommandLong command_;
  bool pending_send_ = false;
  double sent_at_s_ = 0.0;
  int attempts_ = 0;
  std::uint8_t last_result_ = 0;
  CommandCounts counts_;
};

}  // namespace kestrel::mavlink
