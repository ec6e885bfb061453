#include "offboard_rules.hpp"

#include <fmt/format.h>

#include <cmath>

namespace kestrel::sim_autopilot {

namespace mav = mavlink::mav;

namespace {

constexpr std::uint32_t px4_custom_mode(std::uint32_t main, std::uint32_t sub = 0) { return main << 16 | sub << 24; }
constexpr float force_disarm_magic = 21196.0f;  // COMPONENT_ARM_DISARM param2: disarm even in the air

}  // namespace

const char* OffboardRules::mode_name(FlightMode mode) {
  switch (mode) {
    case FlightMode::position:
      return "position";
    case FlightMode::hold:
      return "hold";
    case FlightMode::offboard:
      return "offboard";
  }
  return "?";
}

bool OffboardRules::stream_alive(double now_s) const {
  if (setpoint_times_.empty() || now_s - setpoint_times_.back() > options_.loss_timeout_s) return false;
  std::size_t last_second = 0;
  for (const double t : setpoint_times_) last_second += now_s - t <= 1.0 ? 1 : 0;
  return static_cast<double>(last_second) >= options_.min_setpoint_rate_hz &&
         now_s - stream_since_s_ >= options_.min_stream_s - 1e-9;
}

OffboardRules::Response OffboardRules::on_frame(const mavlink::Frame& frame, double now_s, bool landed) {
  Response out;
  const auto for_us = [&](std::uint8_t system, std::uint8_t component) {
    return (system == 0 || system == options_.system_id) && (component == 0 || component == options_.component_id);
  };
  auto take_setpoint = [&](const auto& target) {
    if (!for_us(target.target_system, target.target_component)) return;
    ++counts_.setpoints;
    if (!latest_ || now_s - latest_->received_s > options_.loss_timeout_s) stream_since_s_ = now_s;  // a new stream
    latest_ = ActiveSetpoint{target, now_s};
    setpoint_times_.push_back(now_s);
    while (!setpoint_times_.empty() && now_s - setpoint_times_.front() > 1.0) setpoint_times_.pop_front();
  };
  if (frame.is<mavlink::SetPositionTargetLocalNed>()) {
    take_setpoint(frame.as<mavlink::SetPositionTargetLocalNed>());
  } else if (frame.is<mavlink::SetAttitudeTarget>()) {
    take_setpoint(frame.as<mavlink::SetAttitudeTarget>());
  } else if (frame.is<mavlink::CommandLong>()) {
    const auto command = frame.as<mavlink::CommandLong>();
    if (!for_us(command.target_system, command.target_component)) return out;
    mavlink::CommandAck ack = answer(command, now_s, landed, out.output);
    ack.target_system = frame.system_id;
    ack.target_component = frame.component_id;
    out.ack = ack;
  }
  return out;
}

mavlink::CommandAck OffboardRules::answer(const mavlink::CommandLong& c, double now_s, bool landed,
                                          std::optional<OutputCommand>& output) {
  mavlink::CommandAck ack;
  ack.command = c.command;
  ack.result = mav::result_accepted;
  const auto refuse = [&](std::uint8_t result, const std::string& why) {
    ack.result = result;
    ++counts_.refused_commands;
    say(why);
  };
  switch (c.command) {
    case mav::cmd_component_arm_disarm:
      if (c.param1 == 1.0f) {
        if (!armed_) ++counts_.arms;
        armed_ = true;
      } else if (landed || c.param2 == force_disarm_magic) {
        if (armed_) ++counts_.disarms;
        armed_ = false;
        mode_ = FlightMode::position;
      } else {
        refuse(mav::result_denied, "Disarming denied: not landed");
      }
      break;
    case mav::cmd_do_set_mode: {
      const auto main = static_cast<std::uint32_t>(std::lround(c.param2));
      if (main == 6) {
        if (!stream_alive(now_s)) {
          ++counts_.offboard_refusals;
          refuse(mav::result_temporarily_rejected, "Switching to offboard rejected: no setpoint stream");
        } else if (mode_ != FlightMode::offboard) {
          mode_ = FlightMode::offboard;
          ++counts_.offboard_grants;
          say("Offboard mode");
        }
      } else if (main == 3) {
        mode_ = FlightMode::position;
      } else if (main == 4 && std::lround(c.param3) == 3) {
        mode_ = FlightMode::hold;
      } else {
        refuse(mav::result_unsupported, fmt::format("Mode {} not available on this vehicle", main));
      }
      break;
    }
    case mav::cmd_do_set_servo:
    case mav::cmd_do_set_relay:
      output = OutputCommand{c.command == mav::cmd_do_set_relay, static_cast<int>(std::lround(c.param1)),
                             static_cast<double>(c.param2)};
      ++counts_.outputs;
      break;
    default:
      ack.result = mav::result_unsupported;
      ++counts_.unsupported_commands;
  }
  return ack;
}

void OffboardRules::step(double now_s) {
  if (mode_ == FlightMode::offboard && !(latest_ && now_s - latest_->received_s <= options_.loss_timeout_s)) {
    mode_ = FlightMode::hold;
    ++counts_.offboard_losses;
    say(fmt::format("Offboard lost: no setpoint for {:g} s, holding", options_.loss_timeout_s));
  }
}

std::optional<ActiveSetpoint> OffboardRules::setpoint() const {
  if (mode_ != FlightMode::offboard) return std::nullopt;
  return latest_;
}

mavlink::Heartbeat OffboardRules::heartbeat() const {
  mavlink::Heartbeat hb;
  hb.type = mav::type_quadrotor;
  hb.autopilot = mav::autopilot_px4;
  hb.base_mode = mav::mode_flag_custom_mode_enabled | (armed_ ? mav::mode_flag_safety_armed : 0);
  switch (mode_) {
    case FlightMode::position:
      hb.custom_mode = px4_custom_mode(3);
      break;
    case FlightMode::hold:
      hb.custom_mode = px4_custom_mode(4, 3);
      break;
    case FlightMode::offboard:
      hb.custom_mode = px4_custom_mode(6);
      break;
  }
  hb.system_status = armed_ ? mav::state_active : mav::state_standby;
  return hb;
}

std::vector<std::string> OffboardRules::take_texts() {
  std::vector<std::string> out;
  out.swap(texts_);
  return out;
}

}  // namespace kestrel::sim_autopilot
