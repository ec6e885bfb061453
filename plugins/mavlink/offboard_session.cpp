#include "offboard_session.hpp"

namespace kestrel::mavlink {

namespace {

// An accepted mode shows in the next heartbeat (1 Hz); three of them missing means it did not take.
constexpr double kModeChangeWait_s = 3.0;

CommandLong arm_command(const AutopilotState& a) {
  CommandLong c;
  c.target_system = a.system_id;
  c.target_component = a.component_id;
  c.command = mav::cmd_component_arm_disarm;
  c.param1 = 1;
  return c;
}

std::string outcome(const CommandExchange& x) {
  const std::string what = x.command() == mav::cmd_component_arm_disarm ? "arming" : "the mode request";
  if (x.state() == CommandExchange::State::timed_out) return what + " had no answer";
  return what + " was refused (MAV_RESULT " + std::to_string(x.last_result()) + ")";
}

}  // namespace

bool OffboardSession::streaming() const { return phase_ != Phase::waiting_for_autopilot && phase_ != Phase::link_lost; }

const char* OffboardSession::phase_name() const {
  switch (phase_) {
    case Phase::waiting_for_autopilot:
      return "waiting_for_autopilot";
    case Phase::prestreaming:
      return "prestreaming";
    case Phase::arming:
      return "arming";
    case Phase::requesting_control:
      return "requesting_control";
    case Phase::engaged:
      return "engaged";
    case Phase::released:
      return "released";
    case Phase::refused:
      return "refused";
    case Phase::link_lost:
      return "link_lost";
  }
  return "?";
}

void OffboardSession::give_up(std::string why) {
  refusal_ = std::move(why);
  ++counts_.refusals;
  exchange_.reset();
  phase_ = Phase::refused;
}

void OffboardSession::refused(double now_s) {
  if (exchange_.state() == CommandExchange::State::refused &&
      exchange_.last_result() == mav::result_temporarily_rejected && asked_again_ < options_.retries) {
    ++asked_again_;
    ++counts_.temporary_rejections;
    exchange_.reset();
    phase_ = Phase::prestreaming;
    phase_since_s_ = now_s;
    return;
  }
  give_up(outcome(exchange_));
}

void OffboardSession::request_control(double now_s, const AutopilotState& autopilot) {
  if (autopilot.external_control) {
    phase_ = Phase::engaged;
    return;
  }
  exchange_.start(request_external_control(autopilot.kind, autopilot.system_id, autopilot.component_id), now_s);
  ++counts_.control_requests;
  phase_ = Phase::requesting_control;
  phase_since_s_ = now_s;
}

void OffboardSession::step(double now_s, const AutopilotState& autopilot) {
  if (phase_ == Phase::waiting_for_autopilot || phase_ == Phase::link_lost) {
    if (autopilot.link_up) {
      phase_ = Phase::prestreaming;
      phase_since_s_ = now_s;
    }
    return;
  }
  if (!autopilot.link_up) {
    ++counts_.link_losses;
    exchange_.reset();
    phase_ = Phase::link_lost;
    return;
  }
  switch (phase_) {
    case Phase::prestreaming:
      if (now_s - phase_since_s_ < options_.prestream_s) return;
      if (options_.arm && !autopilot.armed) {
        exchange_.start(arm_command(autopilot), now_s);
        ++counts_.arm_requests;
        phase_ = Phase::arming;
      } else {
        request_control(now_s, autopilot);
      }
      return;
    case Phase::arming:
      if (exchange_.state() == CommandExchange::State::accepted || autopilot.armed) {
        exchange_.reset();
        request_control(now_s, autopilot);
      } else if (exchange_.state() == CommandExchange::State::refused ||
                 exchange_.state() == CommandExchange::State::timed_out) {
        refused(now_s);
      }
      return;
    case Phase::requesting_control:
      if (autopilot.external_control) {
        exchange_.reset();
        phase_ = Phase::engaged;
      } else if (exchange_.state() == CommandExchange::State::accepted && now_s - phase_since_s_ > kModeChangeWait_s) {
        give_up("the mode request was accepted but the heartbeats never showed the mode");
      } else if (exchange_.state() == CommandExchange::State::refused ||
                 exchange_.state() == CommandExchange::State::timed_out) {
        refused(now_s);
      }
      return;
    case Phase::engaged:
      if (!autopilot.external_control) {
        ++counts_.releases;
        phase_ = Phase::released;
      }
      return;
    default:
      return;  // released, refused: keep streaming, ask nothing
  }
}

}  // namespace kestrel::mavlink
