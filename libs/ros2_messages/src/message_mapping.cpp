#include "kestrel/ros2_messages/message_mapping.hpp"

#include "fields.hpp"

namespace kestrel::ros2 {

namespace {

const std::vector<detail::TypeCodec>& codecs() {
  static const std::vector<detail::TypeCodec> table = [] {
    std::vector<detail::TypeCodec> t = {
        detail::stereo_frame_codec(), detail::point_cloud_codec(),   detail::detections_codec(), detail::tracks_codec(),
        detail::ground_truth_codec(), detail::vehicle_state_codec(), detail::imu_codec()};
    for (auto& c : detail::control_codecs()) t.push_back(c);
    return t;
  }();
  return table;
}

const detail::TypeCodec* find(std::string_view type) {
  for (const auto& c : codecs())
    if (c.type == type) return &c;
  return nullptr;
}

const detail::TypeCodec& get(std::string_view type) {
  if (const auto* c = find(type)) return *c;
  throw Error("no ROS 2 mapping for messages of type " + std::string(type));
}

}  // namespace

bool can_encode(std::string_view kestrel_type) { return find(kestrel_type) != nullptr; }

std::vector<std::string> encodable_types() {
  std::vector<std::string> out;
  for (const auto& c : codecs()) out.emplace_back(c.type);
  return out;
}

std::vector<ChannelSpec> channels_for(std::string_view kestrel_type, const std::string& topic) {
  return get(kestrel_type).channels(topic);
}

Encoded encode(std::string_view kestrel_type, const void* message, const std::string& topic) {
  return get(kestrel_type).encode(message, topic);
}

std::unique_ptr<Decoder> make_decoder(std::string_view kestrel_type) {
  const auto* c = find(kestrel_type);
  return c && c->decoder ? c->decoder() : nullptr;
}

}  // namespace kestrel::ros2
