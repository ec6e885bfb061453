// kestrel.VehicleState: nav_msgs/msg/Odometry from "world" to the publishing node's body frame
// (child_frame_id = NODE), with a derived tf2_msgs/msg/TFMessage on /tf so that viewers place the
// vehicle. As nav_msgs/Odometry specifies, the twist is in the child (body) frame: the world
// velocity is rotated into it, and back on replay, to within rounding.
#include <kestrel/messages/vehicle_state.hpp>

#include "fields.hpp"

namespace kestrel::ros2::detail {

// Named, so that the codecs, which use the same names for their parts, can share a translation unit.
namespace vehicle_state {

std::string body_frame(const std::string& topic) {
  const auto start = topic.find_first_not_of('/');
  if (start == std::string::npos) return "body";
  return topic.substr(start, topic.find('/', start) - start);
}

std::vector<ChannelSpec> channels(const std::string& topic) {
  return {{topic, "nav_msgs/msg/Odometry", false}, {"/tf", "tf2_msgs/msg/TFMessage", true}};
}

Encoded encode(const void* message, const std::string& topic) {
  const auto& s = *static_cast<const msg::VehicleState*>(message);
  const std::string child = body_frame(topic);
  CdrWriter w;
  write_header(w, s.stamp, "world");
  w.string(child);
  write_xyz(w, s.position);
  write_quaternion(w, s.orientation);
  for (int i = 0; i < 36; ++i) w.f64(0.0);  // pose covariance: not estimated
  write_xyz(w, s.orientation.conjugate() * s.velocity);
  write_xyz(w, s.angular_velocity);
  for (int i = 0; i < 36; ++i) w.f64(0.0);
  Encoded out;
  out.messages.push_back({0, w.take(), std::nullopt});
  out.messages.push_back({1, tf_message(s.stamp, "world", child, s.position, s.orientation), std::nullopt});
  return out;
}

msg::VehicleState read(CdrReader& r) {
  msg::VehicleState s;
  s.stamp = read_header(r).stamp;
  r.string();  // child_frame_id
  s.position = read_xyz(r);
  s.orientation = read_quaternion(r);
  for (int i = 0; i < 36; ++i) r.f64();
  s.velocity = s.orientation * read_xyz(r);
  s.angular_velocity = read_xyz(r);
  for (int i = 0; i < 36; ++i) r.f64();
  return s;
}

}  // namespace vehicle_state

TypeCodec vehicle_state_codec() {
  using namespace vehicle_state;
  return {MessageTraits<msg::VehicleState>::name, channels, encode,
          [] { return single_channel_decoder<msg::VehicleState>("nav_msgs/msg/Odometry", read); }};
}

}  // namespace kestrel::ros2::detail
