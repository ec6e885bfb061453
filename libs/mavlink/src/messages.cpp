// Field lists in common.xml's order (minimal.xml for HEARTBEAT); extensions marked as such.
#include "kestrel/mavlink/messages.hpp"

#include <algorithm>
#include <cstring>
#include <map>

namespace kestrel::mavlink {

namespace {
constexpr FieldPart ext = FieldPart::extension;
}

const MessageDefinition& Heartbeat::definition() {
  using M = Heartbeat;
  static const MessageDefinition d(
      0, "HEARTBEAT",
      {field<&M::type>("type"), field<&M::autopilot>("autopilot"), field<&M::base_mode>("base_mode"),
       field<&M::custom_mode>("custom_mode"), field<&M::system_status>("system_status"),
       field<&M::mavlink_version>("mavlink_version")});
  return d;
}

const MessageDefinition& SysStatus::definition() {
  using M = SysStatus;
  static const MessageDefinition d(
      1, "SYS_STATUS",
      {field<&M::onboard_control_sensors_present>("onboard_control_sensors_present"),
       field<&M::onboard_control_sensors_enabled>("onboard_control_sensors_enabled"),
       field<&M::onboard_control_sensors_health>("onboard_control_sensors_health"), field<&M::load>("load"),
       field<&M::voltage_battery>("voltage_battery"), field<&M::current_battery>("current_battery"),
       field<&M::battery_remaining>("battery_remaining"), field<&M::drop_rate_comm>("drop_rate_comm"),
       field<&M::errors_comm>("errors_comm"), field<&M::errors_count1>("errors_count1"),
       field<&M::errors_count2>("errors_count2"), field<&M::errors_count3>("errors_count3"),
       field<&M::errors_count4>("errors_count4"),
       field<&M::onboard_control_sensors_present_extended>("onboard_control_sensors_present_extended", ext),
       field<&M::onboard_control_sensors_enabled_extended>("onboard_control_sensors_enabled_extended", ext),
       field<&M::onboard_control_sensors_health_extended>("onboard_control_sensors_health_extended", ext)});
  return d;
}

const MessageDefinition& AttitudeQuaternion::definition() {
  using M = AttitudeQuaternion;
  static const MessageDefinition d(
      31, "ATTITUDE_QUATERNION",
      {field<&M::time_boot_ms>("time_boot_ms"), field<&M::q1>("q1"), field<&M::q2>("q2"), field<&M::q3>("q3"),
       field<&M::q4>("q4"), field<&M::rollspeed>("rollspeed"), field<&M::pitchspeed>("pitchspeed"),
       field<&M::yawspeed>("yawspeed"), field<&M::repr_offset_q>("repr_offset_q", ext)});
  return d;
}

const MessageDefinition& LocalPositionNed::definition() {
  using M = LocalPositionNed;
  static const MessageDefinition d(32, "LOCAL_POSITION_NED",
                                   {field<&M::time_boot_ms>("time_boot_ms"), field<&M::x>("x"), field<&M::y>("y"),
                                    field<&M::z>("z"), field<&M::vx>("vx"), field<&M::vy>("vy"), field<&M::vz>("vz")});
  return d;
}

const MessageDefinition& CommandLong::definition() {
  using M = CommandLong;
  static const MessageDefinition d(
      76, "COMMAND_LONG",
      {field<&M::target_system>("target_system"), field<&M::target_component>("target_component"),
       field<&M::command>("command"), field<&M::confirmation>("confirmation"), field<&M::param1>("param1"),
       field<&M::param2>("param2"), field<&M::param3>("param3"), field<&M::param4>("param4"),
       field<&M::param5>("param5"), field<&M::param6>("param6"), field<&M::param7>("param7")});
  return d;
}

const MessageDefinition& CommandAck::definition() {
  using M = CommandAck;
  static const MessageDefinition d(
      77, "COMMAND_ACK",
      {field<&M::command>("command"), field<&M::result>("result"), field<&M::progress>("progress", ext),
       field<&M::result_param2>("result_param2", ext), field<&M::target_system>("target_system", ext),
       field<&M::target_component>("target_component", ext)});
  return d;
}

const MessageDefinition& SetAttitudeTarget::definition() {
  using M = SetAttitudeTarget;
  static const MessageDefinition d(
      82, "SET_ATTITUDE_TARGET",
      {field<&M::time_boot_ms>("time_boot_ms"), field<&M::target_system>("target_system"),
       field<&M::target_component>("target_component"), field<&M::type_mask>("type_mask"), field<&M::q>("q"),
       field<&M::body_roll_rate>("body_roll_rate"), field<&M::body_pitch_rate>("body_pitch_rate"),
       field<&M::body_yaw_rate>("body_yaw_rate"), field<&M::thrust>("thrust"),
       field<&M::thrust_body>("thrust_body", ext)});
  return d;
}

const MessageDefinition& AttitudeTarget::definition() {
  using M = AttitudeTarget;
  static const MessageDefinition d(
      83, "ATTITUDE_TARGET",
      {field<&M::time_boot_ms>("time_boot_ms"), field<&M::type_mask>("type_mask"), field<&M::q>("q"),
       field<&M::body_roll_rate>("body_roll_rate"), field<&M::body_pitch_rate>("body_pitch_rate"),
       field<&M::body_yaw_rate>("body_yaw_rate"), field<&M::thrust>("thrust")});
  return d;
}

const MessageDefinition& SetPositionTargetLocalNed::definition() {
  using M = SetPositionTargetLocalNed;
  static const MessageDefinition d(
      84, "SET_POSITION_TARGET_LOCAL_NED",
      {field<&M::time_boot_ms>("time_boot_ms"), field<&M::target_system>("target_system"),
       field<&M::target_component>("target_component"), field<&M::coordinate_frame>("coordinate_frame"),
       field<&M::type_mask>("type_mask"), field<&M::x>("x"), field<&M::y>("y"), field<&M::z>("z"), field<&M::vx>("vx"),
       field<&M::vy>("vy"), field<&M::vz>("vz"), field<&M::afx>("afx"), field<&M::afy>("afy"), field<&M::afz>("afz"),
       field<&M::yaw>("yaw"), field<&M::yaw_rate>("yaw_rate")});
  return d;
}

const MessageDefinition& PositionTargetLocalNed::definition() {
  using M = PositionTargetLocalNed;
  static const MessageDefinition d(
      85, "POSITION_TARGET_LOCAL_NED",
      {field<&M::time_boot_ms>("time_boot_ms"), field<&M::coordinate_frame>("coordinate_frame"),
       field<&M::type_mask>("type_mask"), field<&M::x>("x"), field<&M::y>("y"), field<&M::z>("z"), field<&M::vx>("vx"),
       field<&M::vy>("vy"), field<&M::vz>("vz"), field<&M::afx>("afx"), field<&M::afy>("afy"), field<&M::afz>("afz"),
       field<&M::yaw>("yaw"), field<&M::yaw_rate>("yaw_rate")});
  return d;
}

const MessageDefinition& ExtendedSysState::definition() {
  using M = ExtendedSysState;
  static const MessageDefinition d(245, "EXTENDED_SYS_STATE",
                                   {field<&M::vtol_state>("vtol_state"), field<&M::landed_state>("landed_state")});
  return d;
}

const MessageDefinition& StatusText::definition() {
  using M = StatusText;
  static const MessageDefinition d(253, "STATUSTEXT",
                                   {field<&M::severity>("severity"), field<&M::text>("text"), field<&M::id>("id", ext),
                                    field<&M::chunk_seq>("chunk_seq", ext)});
  return d;
}

std::string StatusText::text_string() const {
  const auto end = std::find(text.begin(), text.end(), '\0');
  return std::string(text.begin(), end);
}

void StatusText::set_text(const std::string& s) {
  text.fill('\0');
  std::memcpy(text.data(), s.data(), std::min(s.size(), text.size()));
}

const MessageDefinition& SetupSigning::definition() {
  using M = SetupSigning;
  static const MessageDefinition d(
      256, "SETUP_SIGNING",
      {field<&M::target_system>("target_system"), field<&M::target_component>("target_component"),
       field<&M::secret_key>("secret_key"), field<&M::initial_timestamp>("initial_timestamp")});
  return d;
}

const MessageDefinition& Odometry::definition() {
  using M = Odometry;
  static const MessageDefinition d(
      331, "ODOMETRY",
      {field<&M::time_usec>("time_usec"), field<&M::frame_id>("frame_id"), field<&M::child_frame_id>("child_frame_id"),
       field<&M::x>("x"), field<&M::y>("y"), field<&M::z>("z"), field<&M::q>("q"), field<&M::vx>("vx"),
       field<&M::vy>("vy"), field<&M::vz>("vz"), field<&M::rollspeed>("rollspeed"), field<&M::pitchspeed>("pitchspeed"),
       field<&M::yawspeed>("yawspeed"), field<&M::pose_covariance>("pose_covariance"),
       field<&M::velocity_covariance>("velocity_covariance"), field<&M::reset_counter>("reset_counter", ext),
       field<&M::estimator_type>("estimator_type", ext), field<&M::quality>("quality", ext)});
  return d;
}

Heartbeat ground_station_heartbeat() {
  Heartbeat hb;
  hb.type = mav::type_gcs;
  hb.autopilot = mav::autopilot_invalid;
  hb.system_status = mav::state_active;
  return hb;
}

const std::vector<const MessageDefinition*>& known_definitions() {
  static const std::vector<const MessageDefinition*> all = {&Heartbeat::definition(),
                                                            &SysStatus::definition(),
                                                            &AttitudeQuaternion::definition(),
                                                            &LocalPositionNed::definition(),
                                                            &CommandLong::definition(),
                                                            &CommandAck::definition(),
                                                            &SetAttitudeTarget::definition(),
                                                            &AttitudeTarget::definition(),
                                                            &SetPositionTargetLocalNed::definition(),
                                                            &PositionTargetLocalNed::definition(),
                                                            &ExtendedSysState::definition(),
                                                            &StatusText::definition(),
                                                            &SetupSigning::definition(),
                                                            &Odometry::definition()};
  return all;
}

const MessageDefinition* find_definition(std::uint32_t id) {
  static const std::map<std::uint32_t, const MessageDefinition*> by_id = [] {
    std::map<std::uint32_t, const MessageDefinition*> m;
    for (const MessageDefinition* d : known_definitions()) m[d->id()] = d;
    return m;
  }();
  const auto it = by_id.find(id);
  return it == by_id.end() ? nullptr : it->second;
}

}  // namespace kestrel::mavlink
