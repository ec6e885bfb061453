// What the detection chain and the trackers publish, and the simulator's truth: kestrel_msgs
// types made of standard ones (ROS 2 has no standard type for them), each with a derived
// visualization_msgs/msg/MarkerArray on ".../markers" for viewers.
#include <cmath>
#include <kestrel/messages/detections.hpp>
#include <kestrel/messages/ground_truth.hpp>
#include <kestrel/messages/tracks.hpp>

#include "fields.hpp"
#include "markers.hpp"

namespace kestrel::ros2::detail {

namespace {

std::vector<ChannelSpec> with_markers(const std::string& topic, const char* schema) {
  return {{topic, schema, false}, {topic + "/markers", "visualization_msgs/msg/MarkerArray", true}};
}

// ---- kestrel.Detections: kestrel_msgs/msg/Detections, a cube per detection.

msg::Detections read_detections(CdrReader& r) {
  msg::Detections d;
  const Header h = read_header(r);
  d.stamp = h.stamp;
  d.frame = h.frame_id;
  d.items.resize(r.sequence_length(56));
  for (auto& item : d.items) {
    item.position = read_xyz(r);
    item.extent = read_xyz(r);
    item.point_count = r.i32();
    item.confidence = r.f64();
  }
  return d;
}

Encoded encode_detections(const void* message, const std::string&) {
  const auto& d = *static_cast<const msg::Detections*>(message);
  CdrWriter w;
  write_header(w, d.stamp, d.frame);
  w.sequence_length(d.items.size());
  std::vector<MarkerSpec> markers;
  for (const auto& item : d.items) {
    write_xyz(w, item.position);
    write_xyz(w, item.extent);
    w.i32(item.point_count);
    w.f64(item.confidence);
    MarkerSpec m;
    m.ns = "detections";
    m.id = static_cast<std::int32_t>(markers.size());
    m.position = item.position;
    m.scale = item.extent.cwiseMax(Eigen::Vector3d::Constant(0.05));
    m.rgba = {1.0f, 0.55f, 0.0f, 0.6f};
    markers.push_back(m);
  }
  Encoded out;
  out.messages.push_back({0, w.take(), std::nullopt});
  out.messages.push_back({1, marker_array(d.stamp, d.frame, markers), std::nullopt});
  return out;
}

// ---- kestrel.Tracks: kestrel_msgs/msg/Tracks (state and covariance as float64[], the
// covariance row-major), a sphere per track and a label with its id; the selected one in red.

msg::Tracks read_tracks(CdrReader& r) {
  msg::Tracks t;
  const Header h = read_header(r);
  t.stamp = h.stamp;
  t.frame = h.frame_id;
  t.items.resize(r.sequence_length(48));
  for (auto& track : t.items) {
    track.id = r.u64();
    track.age = r.i32();
    track.hits = r.i32();
    track.misses = r.i32();
    const std::uint32_t n = r.sequence_length(8);
    track.state.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) track.state[i] = r.f64();
    const std::uint32_t nn = r.sequence_length(8);
    const auto side = static_cast<Eigen::Index>(std::llround(std::sqrt(static_cast<double>(nn))));
    if (side * side != nn) throw CdrError("a track covariance of " + std::to_string(nn) + " values is not square");
    track.covariance.resize(side, side);
    for (Eigen::Index row = 0; row < side; ++row)
      for (Eigen::Index col = 0; col < side; ++col) track.covariance(row, col) = r.f64();
    track.detection = read_xyz(r);
  }
  const bool has_selected = r.boolean();
  const std::uint64_t selected = r.u64();
  if (has_selected) t.selected_id = selected;
  return t;
}

Encoded encode_tracks(const void* message, const std::string&) {
  const auto& t = *static_cast<const msg::Tracks*>(message);
  CdrWriter w;
  write_header(w, t.stamp, t.frame);
  w.sequence_length(t.items.size());
  std::vector<MarkerSpec> markers;
  for (const auto& track : t.items) {
    if (track.covariance.rows() != track.covariance.cols()) throw Error("a track's covariance is not square");
    w.u64(track.id);
    w.i32(track.age);
    w.i32(track.hits);
    w.i32(track.misses);
    w.sequence_length(static_cast<std::size_t>(track.state.size()));
    for (Eigen::Index i = 0; i < track.state.size(); ++i) w.f64(track.state[i]);
    w.sequence_length(static_cast<std::size_t>(track.covariance.size()));
    for (Eigen::Index row = 0; row < track.covariance.rows(); ++row)
      for (Eigen::Index col = 0; col < track.covariance.cols(); ++col) w.f64(track.covariance(row, col));
    write_xyz(w, track.detection);
    if (track.state.size() < 3) continue;
    const bool selected = t.selected_id && *t.selected_id == track.id;
    MarkerSpec m;
    m.shape = MarkerSpec::sphere;
    m.ns = "tracks";
    m.id = static_cast<std::int32_t>(track.id);
    m.position = track.state.head<3>();
    m.scale = Eigen::Vector3d::Constant(0.3);
    m.rgba = selected ? std::array<float, 4>{1.0f, 0.1f, 0.1f, 0.8f} : std::array<float, 4>{0.2f, 0.6f, 1.0f, 0.8f};
    markers.push_back(m);
    MarkerSpec label = m;
    label.shape = MarkerSpec::text;
    label.ns = "track_ids";
    label.position.y() -= 0.3;  // above it: the camera frame's y points down
    label.scale = Eigen::Vector3d::Constant(0.2);
    label.rgba = {1.0f, 1.0f, 1.0f, 1.0f};
    label.label = "track " + std::to_string(track.id);
    markers.push_back(label);
  }
  w.boolean(t.selected_id.has_value());
  w.u64(t.selected_id.value_or(0));
  Encoded out;
  out.messages.push_back({0, w.take(), std::nullopt});
  out.messages.push_back({1, marker_array(t.stamp, t.frame, markers), std::nullopt});
  return out;
}

// ---- kestrel.GroundTruth: kestrel_msgs/msg/GroundTruth, a green sphere per object (world).

msg::GroundTruth read_truth(CdrReader& r) {
  msg::GroundTruth g;
  g.stamp = read_header(r).stamp;
  g.objects.resize(r.sequence_length(81));
  for (auto& o : g.objects) {
    o.id = r.u64();
    o.position_world = read_xyz(r);
    o.position_camera = read_xyz(r);
    o.velocity_world = read_xyz(r);
    o.in_view = r.boolean();
  }
  return g;
}

Encoded encode_truth(const void* message, const std::string&) {
  const auto& g = *static_cast<const msg::GroundTruth*>(message);
  CdrWriter w;
  write_header(w, g.stamp, "world");
  w.sequence_length(g.objects.size());
  std::vector<MarkerSpec> markers;
  for (const auto& o : g.objects) {
    w.u64(o.id);
    write_xyz(w, o.position_world);
    write_xyz(w, o.position_camera);
    write_xyz(w, o.velocity_world);
    w.boolean(o.in_view);
    MarkerSpec m;
    m.shape = MarkerSpec::sphere;
    m.ns = "truth";
    m.id = static_cast<std::int32_t>(o.id);
    m.position = o.position_world;
    m.scale = Eigen::Vector3d::Constant(0.25);
    m.rgba = {0.1f, 0.9f, 0.2f, 0.7f};
    markers.push_back(m);
  }
  Encoded out;
  out.messages.push_back({0, w.take(), std::nullopt});
  out.messages.push_back({1, marker_array(g.stamp, "world", markers), std::nullopt});
  return out;
}

}  // namespace

TypeCodec detections_codec() {
  return {MessageTraits<msg::Detections>::name,
          [](const std::string& topic) { return with_markers(topic, "kestrel_msgs/msg/Detections"); },
          encode_detections,
          [] { return single_channel_decoder<msg::Detections>("kestrel_msgs/msg/Detections", read_detections); }};
}

TypeCodec tracks_codec() {
  return {MessageTraits<msg::Tracks>::name,
          [](const std::string& topic) { return with_markers(topic, "kestrel_msgs/msg/Tracks"); }, encode_tracks,
          [] { return single_channel_decoder<msg::Tracks>("kestrel_msgs/msg/Tracks", read_tracks); }};
}

TypeCodec ground_truth_codec() {
  return {MessageTraits<msg::GroundTruth>::name,
          [](const std::string& topic) { return with_markers(topic, "kestrel_msgs/msg/GroundTruth"); }, encode_truth,
          [] { return single_channel_decoder<msg::GroundTruth>("kestrel_msgs/msg/GroundTruth", read_truth); }};
}

}  // namespace kestrel::ros2::detail
