// The control loop's messages: setpoints, commands, the fire order and the capture. ROS 2 has no
// standard type for any of them; each is a kestrel_msgs type of one channel.
#include <kestrel/messages/actuator_command.hpp>
#include <kestrel/messages/attitude_target.hpp>
#include <kestrel/messages/net_capture.hpp>
#include <kestrel/messages/net_fire.hpp>
#include <kestrel/messages/net_launcher.hpp>
#include <kestrel/messages/trajectory_setpoint.hpp>

#include "fields.hpp"

namespace kestrel::ros2::detail {

namespace {

// A codec for a message carried whole on one channel of `Schema`, written by `Write` and read by
// `Read`.
template <class T, const char* Schema, void (*Write)(CdrWriter&, const T&), T (*Read)(CdrReader&)>
TypeCodec single_channel_codec() {
  return {MessageTraits<T>::name,
          [](const std::string& topic) {
            return std::vector<ChannelSpec>{{topic, Schema, false}};
          },
          [](const void* message, const std::string&) {
            CdrWriter w;
            Write(w, *static_cast<const T*>(message));
            Encoded out;
            out.messages.push_back({0, w.take(), std::nullopt});
            return out;
          },
          [] { return single_channel_decoder<T>(Schema, Read); }};
}

constexpr char kSetpoint[] = "kestrel_msgs/msg/TrajectorySetpoint";
void write_setpoint(CdrWriter& w, const msg::TrajectorySetpoint& s) {
  write_header(w, s.stamp, "world");
  write_xyz(w, s.position);
  write_xyz(w, s.velocity);
  write_xyz(w, s.acceleration);
  w.f64(s.yaw);
  w.f64(s.yaw_rate);
}
msg::TrajectorySetpoint read_setpoint(CdrReader& r) {
  msg::TrajectorySetpoint s;
  s.stamp = read_header(r).stamp;
  s.position = read_xyz(r);
  s.velocity = read_xyz(r);
  s.acceleration = read_xyz(r);
  s.yaw = r.f64();
  s.yaw_rate = r.f64();
  return s;
}

constexpr char kActuator[] = "kestrel_msgs/msg/ActuatorCommand";
void write_actuator(CdrWriter& w, const msg::ActuatorCommand& c) {
  write_header(w, c.stamp, "body");
  w.f64(c.thrust_n);
  write_xyz(w, c.torque_nm);
  w.sequence_length(c.rotor_speeds_rad_s.size());
  for (double v : c.rotor_speeds_rad_s) w.f64(v);
}
msg::ActuatorCommand read_actuator(CdrReader& r) {
  msg::ActuatorCommand c;
  c.stamp = read_header(r).stamp;
  c.thrust_n = r.f64();
  c.torque_nm = read_xyz(r);
  c.rotor_speeds_rad_s.resize(r.sequence_length(8));
  for (double& v : c.rotor_speeds_rad_s) v = r.f64();
  return c;
}

constexpr char kAttitude[] = "kestrel_msgs/msg/AttitudeTarget";
void write_attitude(CdrWriter& w, const msg::AttitudeTarget& a) {
  write_header(w, a.stamp, "world");
  write_quaternion(w, a.orientation);
  write_xyz(w, a.body_rates);
  w.f64(a.thrust_n);
  w.f64(a.hover_thrust_n);
}
msg::AttitudeTarget read_attitude(CdrReader& r) {
  msg::AttitudeTarget a;
  a.stamp = read_header(r).stamp;
  a.orientation = read_quaternion(r);
  a.body_rates = read_xyz(r);
  a.thrust_n = r.f64();
  a.hover_thrust_n = r.f64();
  return a;
}

constexpr char kFire[] = "kestrel_msgs/msg/NetFire";
void write_fire(CdrWriter& w, const msg::NetFire& f) {
  write_header(w, f.stamp, "camera");
  w.u64(f.target_id);
  write_xyz(w, f.aim_error_m);
}
msg::NetFire read_fire(CdrReader& r) {
  msg::NetFire f;
  f.stamp = read_header(r).stamp;
  f.target_id = r.u64();
  f.aim_error_m = read_xyz(r);
  return f;
}

constexpr char kCapture[] = "kestrel_msgs/msg/NetCapture";
void write_capture(CdrWriter& w, const msg::NetCapture& c) {
  write_header(w, c.stamp, "world");
  w.u64(c.object_id);
  write_xyz(w, c.position_world);
}
msg::NetCapture read_capture(CdrReader& r) {
  msg::NetCapture c;
  c.stamp = read_header(r).stamp;
  c.object_id = r.u64();
  c.position_world = read_xyz(r);
  return c;
}

constexpr char kLauncher[] = "kestrel_msgs/msg/NetLauncher";
void write_launcher(CdrWriter& w, const msg::NetLauncher& l) {
  write_header(w, l.stamp, "");
  w.i64(l.nets_left);
  w.i64(l.nets_used);
  write_time(w, l.ready_at);
}
msg::NetLauncher read_launcher(CdrReader& r) {
  msg::NetLauncher l;
  l.stamp = read_header(r).stamp;
  l.nets_left = r.i64();
  l.nets_used = r.i64();
  l.ready_at = read_time(r);
  return l;
}

}  // namespace

std::vector<TypeCodec> control_codecs() {
  return {single_channel_codec<msg::TrajectorySetpoint, kSetpoint, write_setpoint, read_setpoint>(),
          single_channel_codec<msg::ActuatorCommand, kActuator, write_actuator, read_actuator>(),
          single_channel_codec<msg::AttitudeTarget, kAttitude, write_attitude, read_attitude>(),
          single_channel_codec<msg::NetFire, kFire, write_fire, read_fire>(),
          single_channel_codec<msg::NetCapture, kCapture, write_capture, read_capture>(),
          single_channel_codec<msg::NetLauncher, kLauncher, write_launcher, read_launcher>()};
}

}  // namespace kestrel::ros2::detail
