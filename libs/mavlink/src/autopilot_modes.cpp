#include "kestrel/mavlink/autopilot_modes.hpp"

namespace kestrel::mavlink {

namespace {

constexpr std::uint32_t px4_main(std::uint32_t custom_mode) { return (custom_mode >> 16) & 0xFF; }
constexpr std::uint32_t px4_sub(std::uint32_t custom_mode) { return (custom_mode >> 24) & 0xFF; }
constexpr std::uint8_t px4_offboard = 6, arducopter_guided = 4;

std::string px4_mode(std::uint32_t custom_mode) {
  switch (px4_main(custom_mode)) {
    case 1:
      return "manual";
    case 2:
      return "altitude";
    case 3:
      return "position";
    case 4:
      switch (px4_sub(custom_mode)) {
        case 2:
          return "takeoff";
        case 3:
          return "hold";
        case 4:
          return "mission";
        case 5:
          return "return";
        case 6:
          return "land";
        default:
          return "auto";
      }
    case 5:
      return "acro";
    case 6:
      return "offboard";
    case 7:
      return "stabilized";
    default:
      return "custom " + std::to_string(custom_mode);
  }
}

std::string arducopter_mode(std::uint32_t custom_mode) {
  switch (custom_mode) {
    case 0:
      return "stabilize";
    case 1:
      return "acro";
    case 2:
      return "alt_hold";
    case 3:
      return "auto";
    case 4:
      return "guided";
    case 5:
      return "loiter";
    case 6:
      return "rtl";
    case 7:
      return "circle";
    case 9:
      return "land";
    case 16:
      return "poshold";
    case 17:
      return "brake";
    case 20:
      return "guided_nogps";
    case 21:
      return "smart_rtl";
    default:
      return "custom " + std::to_string(custom_mode);
  }
}

}  // namespace

AutopilotKind autopilot_kind(std::uint8_t mav_autopilot) {
  if (mav_autopilot == mav::autopilot_px4) return AutopilotKind::px4;
  if (mav_autopilot == mav::autopilot_ardupilotmega) return AutopilotKind::ardupilot;
  return AutopilotKind::generic;
}

const char* autopilot_name(AutopilotKind kind) {
  switch (kind) {
    case AutopilotKind::px4:
      return "px4";
    case AutopilotKind::ardupilot:
      return "ardupilot";
    default:
      return "generic";
  }
}

std::string mode_name(AutopilotKind kind, std::uint32_t custom_mode) {
  if (kind == AutopilotKind::px4) return px4_mode(custom_mode);
  if (kind == AutopilotKind::ardupilot) return arducopter_mode(custom_mode);
  return "custom " + std::to_string(custom_mode);
}

bool is_armed(const Heartbeat& heartbeat) { return (heartbeat.base_mode & mav::mode_flag_safety_armed) != 0; }

bool in_external_control(AutopilotKind kind, const Heartbeat& heartbeat) {
  if ((heartbeat.base_mode & mav::mode_flag_custom_mode_enabled) == 0) return false;
  if (kind == AutopilotKind::px4) return px4_main(heartbeat.custom_mode) == px4_offboard;
  if (kind == AutopilotKind::ardupilot) return heartbeat.custom_mode == arducopter_guided;
  return false;
}

CommandLong request_external_control(AutopilotKind kind, std::uint8_t target_system, std::uint8_t target_component) {
  CommandLong c;
  c.target_system = target_system;
  c.target_component = target_component;
  c.command = mav::cmd_do_set_mode;
  c.param1 = mav::mode_flag_custom_mode_enabled;
  c.param2 = kind == AutopilotKind::ardupilot ? arducopter_guided : px4_offboard;
  return c;
}

}  // namespace kestrel::mavlink
