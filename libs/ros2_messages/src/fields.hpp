#pragma once
// Private to the mapping: the standard ROS 2 fields every mapped message is built from, written
// and read in CDR, and the table entry each kestrel message type gives.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <string>

#include "kestrel/ros2/cdr.hpp"
#include "kestrel/ros2_messages/message_mapping.hpp"
#include "kestrel/time.hpp"

namespace kestrel::ros2::detail {

/// builtin_interfaces/Time: whole seconds (rounded down) and nanoseconds in [0, 1e9), so that
/// every int64 stamp within ±68 years round-trips.
inline void write_time(CdrWriter& w, Time t) {
  const std::int64_t ns = t.count();
  std::int64_t sec = ns / 1'000'000'000;
  std::int64_t rest = ns % 1'000'000'000;
  if (rest < 0) {
    rest += 1'000'000'000;
    --sec;
  }
  w.i32(static_cast<std::int32_t>(sec));
  w.u32(static_cast<std::uint32_t>(rest));
}
inline Time read_time(CdrReader& r) {
  const std::int64_t sec = r.i32();
  const std::int64_t nanosec = r.u32();
  return Time(sec * 1'000'000'000 + nanosec);
}

/// std_msgs/Header
inline void write_header(CdrWriter& w, Time stamp, const std::string& frame_id) {
  write_time(w, stamp);
  w.string(frame_id);
}
struct Header {
  Time stamp{0};
  std::string frame_id;
};
inline Header read_header(CdrReader& r) {
  Header h;
  h.stamp = read_time(r);
  h.frame_id = r.string();
  return h;
}

/// geometry_msgs/Point and Vector3: three float64.
inline void write_xyz(CdrWriter& w, const Eigen::Vector3d& v) {
  w.f64(v.x());
  w.f64(v.y());
  w.f64(v.z());
}
inline Eigen::Vector3d read_xyz(CdrReader& r) {
  const double x = r.f64(), y = r.f64(), z = r.f64();
  return {x, y, z};
}
/// geometry_msgs/Quaternion: x, y, z, w.
inline void write_quaternion(CdrWriter& w, const Eigen::Quaterniond& q) {
  w.f64(q.x());
  w.f64(q.y());
  w.f64(q.z());
  w.f64(q.w());
}
inline Eigen::Quaterniond read_quaternion(CdrReader& r) {
  const double x = r.f64(), y = r.f64(), z = r.f64(), w = r.f64();
  return Eigen::Quaterniond(w, x, y, z);
}

/// tf2_msgs/TFMessage holding one geometry_msgs/TransformStamped: `child`'s pose in `parent`.
inline std::vector<std::uint8_t> tf_message(Time stamp, const std::string& parent, const std::string& child,
                                            const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation) {
  CdrWriter w;
  w.sequence_length(1);
  write_header(w, stamp, parent);
  w.string(child);
  write_xyz(w, position);
  write_quaternion(w, orientation);
  return w.take();
}

/// Checks that a decoded message used all its bytes (CDR pads to at most 3 more).
inline void expect_end(const CdrReader& r, const char* type) {
  if (r.remaining() > 3) throw CdrError(std::to_string(r.remaining()) + " bytes left after a whole " + type);
}

/// What one kestrel message type gives the mapping table.
struct TypeCodec {
  std::string_view type;
  std::vector<ChannelSpec> (*channels)(const std::string& topic);
  Encoded (*encode)(const void* message, const std::string& topic);
  std::unique_ptr<Decoder> (*decoder)();  ///< nullptr: not read back
};

// One per file of this folder.
TypeCodec stereo_frame_codec();
TypeCodec point_cloud_codec();
TypeCodec detections_codec();
TypeCodec tracks_codec();
TypeCodec ground_truth_codec();
TypeCodec vehicle_state_codec();
TypeCodec imu_codec();
std::vector<TypeCodec> control_codecs();  // setpoint, actuator command, attitude target, net fire and capture

/// A decoder for types carried whole on one channel: `read` parses one message.
template <class T, class Read>
class SingleChannelDecoder final : public Decoder {
 public:
  SingleChannelDecoder(std::string schema, Read read) : schema_(std::move(schema)), read_(read) {}
  std::vector<ChannelSpec> inputs() const override { return {{"", schema_, false}}; }
  std::shared_ptr<const void> feed(std::size_t, std::span<const std::uint8_t> cdr, std::uint32_t,
                                   const ChannelMetadata&) override {
    CdrReader r(cdr);
    auto message = std::make_shared<T>(read_(r));
    expect_end(r, schema_.c_str());
    return message;
  }

 private:
  std::string schema_;
  Read read_;
};

template <class T, class Read>
std::unique_ptr<Decoder> single_channel_decoder(std::string schema, Read read) {
  return std::make_unique<SingleChannelDecoder<T, Read>>(std::move(schema), read);
}

}  // namespace kestrel::ros2::detail
