#pragma once
// What an autopilot's HEARTBEAT says, read the way each autopilot writes it: PX4 packs a main and
// a sub mode into custom_mode's upper bytes (px4_custom_mode.h), ArduCopter puts its mode number
// there (ArduCopter/mode.h). Also the DO_SET_MODE request for the mode that flies a companion's
// setpoints: PX4 OFFBOARD (main mode 6), ArduCopter GUIDED (4).
#include <cstdint>
#include <string>

#include "kestrel/mavlink/messages.hpp"

namespace kestrel::mavlink {

enum class AutopilotKind { px4, ardupilot, generic };

AutopilotKind autopilot_kind(std::uint8_t mav_autopilot);
const char* autopilot_name(AutopilotKind kind);

/// The flight mode's name in lower case ("offboard", "position", "guided", "loiter", ...), or
/// "custom NNN" for a value the autopilot's table does not name.
std::string mode_name(AutopilotKind kind, std::uint32_t custom_mode);

/// True in the mode that flies a companion's setpoints.
bool in_external_control(AutopilotKind kind, const Heartbeat& heartbeat);
bool is_armed(const Heartbeat& heartbeat);

/// COMMAND_LONG DO_SET_MODE asking for that mode (PX4: param1 custom-mode flag, param2 main mode
/// 6; ArduPilot: param1 the same flag, param2 mode 4).
CommandLong request_external_control(AutopilotKind kind, std::uint8_t target_system, std::uint8_t target_component);

}  // namespace kestrel::mavlink
