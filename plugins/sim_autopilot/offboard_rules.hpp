#pragma once
// The vehicle's side of a companion's MAVLink dealings, as PX4 plays it (the offboard guide and
// commander's rules), with no I/O and no clock of its own: it takes the frames addressed to the
// vehicle and the time, and says what the vehicle does.
// - Offboard is granted only while setpoints stream: one within the loss timeout, at least the
//   minimum rate over the last second, and the stream unbroken for a second (PX4 refuses a mode
//   switch without such a stream).
// - In offboard, setpoints that stop for the loss timeout (COM_OF_LOSS_T) drop the vehicle to hold
//   at where it is (the failsafe COM_OBL_RC_ACT chooses; here: hold).
// - Arming is COMPONENT_ARM_DISARM; disarming in the air is refused unless forced (21196).
// - Every COMMAND_LONG for this vehicle is answered with a COMMAND_ACK; servo and relay commands
//   are carried out and handed to the caller (the net launcher hangs on one).
#include <deque>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "kestrel/mavlink/frame.hpp"
#include "kestrel/mavlink/messages.hpp"

namespace kestrel::sim_autopilot {

struct OffboardRulesOptions {
  double loss_timeout_s = 0.5;        ///< COM_OF_LOSS_T
  double min_setpoint_rate_hz = 2.0;  ///< PX4 leaves offboard below 2 Hz
  double min_stream_s = 1.0;          ///< how long the stream must have run before offboard
  std::uint8_t system_id = 1;
  std::uint8_t component_id = mavlink::mav::comp_autopilot1;
};

/// PX4's main modes (px4_custom_mode.h) that the simulated vehicle flies.
enum class FlightMode { position, hold, offboard };

/// The setpoint being flown: a position target or an attitude target, and when it came.
struct ActiveSetpoint {
  std::variant<mavlink::SetPositionTargetLocalNed, mavlink::SetAttitudeTarget> target;
  double received_s = 0.0;
};

/// A servo or relay output set by DO_SET_SERVO / DO_SET_RELAY.
struct OutputCommand {
  bool relay = false;
  int channel = 0;
  double value = 0.0;  ///< PWM in microseconds (servo) or the relay setting
};

struct OffboardRulesCounts {
  std::uint64_t setpoints = 0;
  std::uint64_t offboard_grants = 0;
  std::uint64_t offboard_refusals = 0;
  std::uint64_t offboard_losses = 0;  ///< setpoints stopped in offboard: dropped to hold
  std::uint64_t arms = 0;
  std::uint64_t disarms = 0;
  std::uint64_t refused_commands = 0;      ///< denied or temporarily rejected
  std::uint64_t unsupported_commands = 0;  ///< commands this vehicle does not know
  std::uint64_t outputs = 0;               ///< servo and relay commands carried out
};

class OffboardRules {
 public:
  explicit OffboardRules(OffboardRulesOptions options = {}) : options_(options) {}

  /// What the vehicle answers a frame with, and what it sets: at most one of each.
  struct Response {
    std::optional<mavlink::CommandAck> ack;
    std::optional<OutputCommand> output;
  };
  /// Takes a frame from the companion at now_s. `landed`: whether the vehicle is on the ground.
  Response on_frame(const mavlink::Frame& frame, double now_s, bool landed);
  /// Applies the loss timeout at now_s.
  void step(double now_s);

  bool armed() const { return armed_; }
  FlightMode mode() const { return mode_; }
  /// The latest setpoint, while in offboard.
  std::optional<ActiveSetpoint> setpoint() const;
  /// The heartbeat the vehicle sends now.
  mavlink::Heartbeat heartbeat() const;
  /// Status texts (mode changes, refusals) since the last call, as PX4 announces them.
  std::vector<std::string> take_texts();
  const OffboardRulesCounts& counts() const { return counts_; }
  static const char* mode_name(FlightMode mode);

 private:
  bool stream_alive(double now_s) const;
  mavlink::CommandAck answer(const mavlink::CommandLong& command, double now_s, bool landed,
                             std::optional<OutputCommand>& output);
  void say(std::string text) { texts_.push_back(std::move(text)); }

  OffboardRulesOptions options_;
  bool armed_ = false;
  FlightMode mode_ = FlightMode::position;
  std::optional<ActiveSetpoint> latest_;
  std::deque<double> setpoint_times_;  // the last second's
  double stream_since_s_ = 0.0;        // the first setpoint of the unbroken stream
  std::vector<std::string> texts_;
  OffboardRulesCounts counts_;
};

}  // namespace kestrel::sim_autopilot
