#pragma once
// The MAVLink messages kestrel speaks, from common.xml (and minimal.xml for HEARTBEAT). Each struct
// holds a message's fields under their XML names; its definition() lists them in XML order, and
// the wire layout and CRC_EXTRA follow from that list (message_definition.hpp), so a test against
// the published CRC_EXTRA constants catches any field typed or ordered wrong.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "kestrel/mavlink/message_definition.hpp"

namespace kestrel::mavlink {

struct Heartbeat {                 // 0
  std::uint8_t type = 0;           ///< MAV_TYPE
  std::uint8_t autopilot = 0;      ///< MAV_AUTOPILOT
  std::uint8_t base_mode = 0;      ///< MAV_MODE_FLAG bits
  std::uint32_t custom_mode = 0;   ///< autopilot-specific mode
  std::uint8_t system_status = 0;  ///< MAV_STATE
  std::uint8_t mavlink_version = 3;
  static const MessageDefinition& definition();
};

struct SysStatus {  // 1
  std::uint32_t onboard_control_sensors_present = 0;
  std::uint32_t onboard_control_sensors_enabled = 0;
  std::uint32_t onboard_control_sensors_health = 0;
  std::uint16_t load = 0;              ///< d%
  std::uint16_t voltage_battery = 0;   ///< mV
  std::int16_t current_battery = -1;   ///< cA
  std::int8_t battery_remaining = -1;  ///< %
  std::uint16_t drop_rate_comm = 0;
  std::uint16_t errors_comm = 0;
  std::uint16_t errors_count1 = 0, errors_count2 = 0, errors_count3 = 0, errors_count4 = 0;
  std::uint32_t onboard_control_sensors_present_extended = 0;
  std::uint32_t onboard_control_sensors_enabled_extended = 0;
  std::uint32_t onboard_control_sensors_health_extended = 0;
  static const MessageDefinition& definition();
};

struct AttitudeQuaternion {  // 31: body FRD to local NED
  std::uint32_t time_boot_ms = 0;
  float q1 = 1, q2 = 0, q3 = 0, q4 = 0;  ///< w, x, y, z
  float rollspeed = 0, pitchspeed = 0, yawspeed = 0;
  std::array<float, 4> repr_offset_q{};
  static const MessageDefinition& definition();
};

struct LocalPositionNed {  // 32
  std::uint32_t time_boot_ms = 0;
  float x = 0, y = 0, z = 0;
  float vx = 0, vy = 0, vz = 0;
  static const MessageDefinition& definition();
};

struct CommandLong {  // 76
  std::uint8_t target_system = 0;
  std::uint8_t target_component = 0;
  std::uint16_t command = 0;  ///< MAV_CMD
  std::uint8_t confirmation = 0;
  float param1 = 0, param2 = 0, param3 = 0, param4 = 0, param5 = 0, param6 = 0, param7 = 0;
  static const MessageDefinition& definition();
};

struct CommandAck {  // 77
  std::uint16_t command = 0;
  std::uint8_t result = 0;  ///< MAV_RESULT
  std::uint8_t progress = 0;
  std::int32_t result_param2 = 0;
  std::uint8_t target_system = 0;
  std::uint8_t target_component = 0;
  static const MessageDefinition& definition();
};

struct SetAttitudeTarget {  // 82
  std::uint32_t time_boot_ms = 0;
  std::uint8_t target_system = 0;
  std::uint8_t target_component = 0;
  std::uint8_t type_mask = 0;  ///< ATTITUDE_TARGET_TYPEMASK: set bits are ignored
  std::array<float, 4> q{1, 0, 0, 0};
  float body_roll_rate = 0, body_pitch_rate = 0, body_yaw_rate = 0;
  float thrust = 0;  ///< 0..1
  std::array<float, 3> thrust_body{};
  static const MessageDefinition& definition();
};

struct AttitudeTarget {  // 83
  std::uint32_t time_boot_ms = 0;
  std::uint8_t type_mask = 0;
  std::array<float, 4> q{1, 0, 0, 0};
  float body_roll_rate = 0, body_pitch_rate = 0, body_yaw_rate = 0;
  float thrust = 0;
  static const MessageDefinition& definition();
};

struct SetPositionTargetLocalNed {  // 84
  std::uint32_t time_boot_ms = 0;
  std::uint8_t target_system = 0;
  std::uint8_t target_component = 0;
  std::uint8_t coordinate_frame = 1;  ///< MAV_FRAME_LOCAL_NED
  std::uint16_t type_mask = 0;        ///< POSITION_TARGET_TYPEMASK: set bits are ignored
  float x = 0, y = 0, z = 0;
  float vx = 0, vy = 0, vz = 0;
  float afx = 0, afy = 0, afz = 0;
  float yaw = 0, yaw_rate = 0;
  static const MessageDefinition& definition();
};

struct PositionTargetLocalNed {  // 85
  std::uint32_t time_boot_ms = 0;
  std::uint8_t coordinate_frame = 1;
  std::uint16_t type_mask = 0;
  float x = 0, y = 0, z = 0;
  float vx = 0, vy = 0, vz = 0;
  float afx = 0, afy = 0, afz = 0;
  float yaw = 0, yaw_rate = 0;
  static const MessageDefinition& definition();
};

struct ExtendedSysState {  // 245
  std::uint8_t vtol_state = 0;
  std::uint8_t landed_state = 0;  ///< MAV_LANDED_STATE
  static const MessageDefinition& definition();
};

struct StatusText {             // 253
  std::uint8_t severity = 6;    ///< MAV_SEVERITY (6 info)
  std::array<char, 50> text{};  ///< not NUL-terminated when 50 characters long
  std::uint16_t id = 0;
  std::uint8_t chunk_seq = 0;
  static const MessageDefinition& definition();
  std::string text_string() const;
  void set_text(const std::string& s);
};

struct SetupSigning {  // 256: MAVLink 2 only; sent only over a link the user trusts
  std::uint8_t target_system = 0;
  std::uint8_t target_component = 0;
  std::array<std::uint8_t, 32> secret_key{};
  std::uint64_t initial_timestamp = 0;  ///< 10 us units since 2015-01-01 UTC (signing.hpp)
  static const MessageDefinition& definition();
};

struct Odometry {  // 331: MAVLink 2 only
  std::uint64_t time_usec = 0;
  std::uint8_t frame_id = 1;         ///< MAV_FRAME of the pose
  std::uint8_t child_frame_id = 12;  ///< MAV_FRAME of the velocities (12 BODY_FRD)
  float x = 0, y = 0, z = 0;
  std::array<float, 4> q{1, 0, 0, 0};
  float vx = 0, vy = 0, vz = 0;
  float rollspeed = 0, pitchspeed = 0, yawspeed = 0;
  std::array<float, 21> pose_covariance{};
  std::array<float, 21> velocity_covariance{};
  std::uint8_t reset_counter = 0;
  std::uint8_t estimator_type = 0;
  std::int8_t quality = 0;
  static const MessageDefinition& definition();
};

/// The heartbeat of a ground station (MAV_TYPE_GCS, no autopilot), as a tool on the ground sends it.
Heartbeat ground_station_heartbeat();

/// Every message above, by id; nullptr for one kestrel does not know.
const MessageDefinition* find_definition(std::uint32_t id);
const std::vector<const MessageDefinition*>& known_definitions();

/// The enum values kestrel uses (common.xml, minimal.xml).
namespace mav {
inline constexpr std::uint8_t type_quadrotor = 2, type_gcs = 6, type_onboard_controller = 18;
inline constexpr std::uint8_t autopilot_generic = 0, autopilot_ardupilotmega = 3, autopilot_invalid = 8,
                              autopilot_px4 = 12;
inline constexpr std::uint8_t mode_flag_custom_mode_enabled = 1, mode_flag_guided_enabled = 8,
                              mode_flag_stabilize_enabled = 16, mode_flag_safety_armed = 128;
inline constexpr std::uint8_t state_standby = 3, state_active = 4, state_critical = 5;
inline constexpr std::uint8_t comp_autopilot1 = 1, comp_onboard_computer = 191;
inline constexpr std::uint16_t cmd_do_set_mode = 176, cmd_do_set_relay = 181, cmd_do_set_servo = 183,
                               cmd_component_arm_disarm = 400;
inline constexpr std::uint8_t result_accepted = 0, result_temporarily_rejected = 1, result_denied = 2,
                              result_unsupported = 3, result_failed = 4, result_in_progress = 5;
inline constexpr std::uint8_t frame_local_ned = 1, frame_body_frd = 12;
inline constexpr std::uint8_t landed_undefined = 0, landed_on_ground = 1, landed_in_air = 2;
inline constexpr std::uint8_t severity_warning = 4, severity_info = 6;
}  // namespace mav

}  // namespace kestrel::mavlink
