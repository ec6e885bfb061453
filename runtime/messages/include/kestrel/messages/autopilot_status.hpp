#pragma once
// What an autopilot says about itself over its link: armed or not, its flight mode, and whether
// the link is alive. The vehicle's motion travels separately, as a VehicleState.
#include <cstdint>
#include <string>

#include "kestrel/message.hpp"

namespace kestrel::msg {

struct AutopilotStatus {
  Time stamp{0};                   ///< when this was last heard (run clock)
  bool link_up = false;            ///< a heartbeat from the autopilot within the link's timeout
  double heartbeat_age_s = 0.0;    ///< time since the autopilot's last heartbeat
  std::string autopilot;           ///< "px4", "ardupilot" or "generic"
  bool armed = false;              ///< the motors may spin
  std::string mode;                ///< the flight mode's name: "offboard", "guided", "position", ...
  bool external_control = false;   ///< in the mode that flies a companion's setpoints (PX4 offboard, ArduPilot GUIDED)
  std::uint32_t custom_mode = 0;   ///< the heartbeat's custom_mode as sent
  std::uint8_t system_status = 0;  ///< MAV_STATE: 3 standby, 4 active, 5 critical, ...
  std::uint8_t landed_state = 0;   ///< MAV_LANDED_STATE: 0 unknown, 1 on ground, 2 in air, ...
  std::uint64_t frames_received = 0;  ///< good frames from the autopilot so far
  std::uint64_t frames_bad = 0;       ///< frames refused so far: bad checksum, unknown flags
};

}  // namespace kestrel::msg

KESTREL_MESSAGE(kestrel::msg::AutopilotStatus, "kestrel.AutopilotStatus",
                "an autopilot's armed state, flight mode and link health");
KESTREL_MESSAGE_FIELDS(
    kestrel::msg::AutopilotStatus, {"stamp", "Time", "ns", "", "when this was last heard"},
    {"link_up", "bool", "", "", "a heartbeat from the autopilot within the link's timeout"},
    {"heartbeat_age_s", "double", "s", "", "time since the autopilot's last heartbeat"},
    {"autopilot", "string", "", "", "px4, ardupilot or generic"}, {"armed", "bool", "", "", "the motors may spin"},
    {"mode", "string", "", "", "the flight mode's name"},
    {"external_control", "bool", "", "", "in the mode that flies a companion's setpoints (offboard, GUIDED)"},
    {"custom_mode", "uint32", "", "", "the heartbeat's custom_mode as sent"},
    {"system_status", "uint8", "", "", "MAV_STATE"}, {"landed_state", "uint8", "", "", "MAV_LANDED_STATE"},
    {"frames_received", "uint64", "", "", "good frames from the autopilot so far"},
    {"frames_bad", "uint64", "", "", "frames refused so far (checksum, flags)"});
