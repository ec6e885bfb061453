#include "command_exchange.hpp"

namespace kestrel::mavlink {

void CommandExchange::start(const CommandLong& command, double /*now_s*/) {
  command_ = command;
  command_.confirmation = 0;
  state_ = State::waiting;
  pending_send_ = true;
  attempts_ = 0;
}

std::optional<CommandLong> CommandExchange::due(double now_s) {
  if (state_ != State::waiting) return std::nullopt;
  if (pending_send_) {
    pending_send_ = false;
    sent_at_s_ = now_s;
    ++attempts_;
    ++counts_.sent;
    return command_;
  }
  if (now_s - sent_at_s_ < timeout_s_) return std::nullopt;
  if (attempts_ > retries_) {
    state_ = State::timed_out;
    ++counts_.timed_out;
    return std::nullopt;
  }
  ++attempts_;
  ++counts_.resent;
  command_.confirmation = static_cast<std::uint8_t>(command_.confirmation + 1);
  sent_at_s_ = now_s;
  return command_;
}

void CommandExchange::on_ack(const CommandAck& ack) {
  if (state_ != State::waiting || ack.command != command_.command) return;
  last_result_ = ack.result;
  if (ack.result == mav::result_in_progress) return;
  if (ack.result == mav::result_accepted) {
    state_ = State::accepted;
    ++counts_.accepted;
  } else {
    state_ = State::refused;
    ++counts_.refused;
  }
}

}  // namespace kestrel::mavlink
