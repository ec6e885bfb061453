#include "markers.hpp"

#include "fields.hpp"

namespace kestrel::ros2::detail {

namespace {

constexpr std::int32_t kAdd = 0;
constexpr std::int32_t kDeleteAll = 3;

void write_marker(CdrWriter& w, Time stamp, const std::string& frame_id, const MarkerSpec& m, std::int32_t action) {
  write_header(w, stamp, frame_id);
  w.string(m.ns);
  w.i32(m.id);
  w.i32(m.shape);
  w.i32(action);
  write_xyz(w, m.position);                             // pose.position
  write_quaternion(w, Eigen::Quaterniond::Identity());  // pose.orientation
  write_xyz(w, m.scale);
  for (float c : m.rgba) w.f32(c);
  w.i32(0);  // lifetime: until replaced
  w.u32(0);
  w.boolean(false);              // frame_locked
  w.sequence_length(0);          // points
  w.sequence_length(0);          // colors
  w.string("");                  // texture_resource
  write_header(w, Time(0), "");  // texture: an empty CompressedImage
  w.string("");
  w.sequence_length(0);
  w.sequence_length(0);  // uv_coordinates
  w.string(m.label);
  w.string("");  // mesh_resource
  w.string("");  // mesh_file: filename, data
  w.sequence_length(0);
  w.boolean(false);  // mesh_use_embedded_materials
}

}  // namespace

std::vector<std::uint8_t> marker_array(Time stamp, const std::string& frame_id,
                                       const std::vector<MarkerSpec>& markers) {
  CdrWriter w;
  w.sequence_length(markers.size() + 1);
  write_marker(w, stamp, frame_id, MarkerSpec{}, kDeleteAll);
  for (const MarkerSpec& m : markers) write_marker(w, stamp, frame_id, m, kAdd);
  return w.take();
}

}  // namespace kestrel::ros2::detail
