// kestrel.PointCloud: sensor_msgs/msg/PointCloud2 with float32 x, y, z (12 bytes a point), one
// row, in the cloud's frame. pixels_per_point and focal_baseline_px_m travel in the channel's
// metadata.
#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <kestrel/messages/point_cloud.hpp>

#include "fields.hpp"

namespace kestrel::ros2::detail {

// Named, so that the codecs, which use the same names for their parts, can share a translation unit.
namespace point_cloud {

constexpr std::uint8_t kFloat32 = 7;  // sensor_msgs/PointField FLOAT32
constexpr std::uint32_t kPointStep = 12;
const char* const kPixelsPerPoint = "kestrel.pixels_per_point";
const char* const kFocalBaseline = "kestrel.focal_baseline_px_m";

std::vector<ChannelSpec> channels(const std::string& topic) { return {{topic, "sensor_msgs/msg/PointCloud2", false}}; }

Encoded encode(const void* message, const std::string&) {
  const auto& c = *static_cast<const msg::PointCloud*>(message);
  if (!c.points) throw Error("a point cloud without points");
  const auto& points = c.points->points;
  CdrWriter w;
  write_header(w, c.stamp, c.frame);
  w.u32(1);
  w.u32(static_cast<std::uint32_t>(points.size()));
  w.sequence_length(3);
  const char* names[3] = {"x", "y", "z"};
  for (std::uint32_t i = 0; i < 3; ++i) {
    w.string(names[i]);
    w.u32(4 * i);
    w.u8(kFloat32);
    w.u32(1);
  }
  w.boolean(false);  // little-endian
  w.u32(kPointStep);
  w.u32(kPointStep * static_cast<std::uint32_t>(points.size()));
  std::vector<std::uint8_t> data(points.size() * kPointStep);
  bool dense = true;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const float xyz[3] = {points[i].x, points[i].y, points[i].z};
    dense = dense && std::isfinite(xyz[0]) && std::isfinite(xyz[1]) && std::isfinite(xyz[2]);
    std::memcpy(data.data() + i * kPointStep, xyz, sizeof xyz);
  }
  w.bytes(data);
  w.boolean(dense);
  Encoded out;
  out.messages.push_back({0, w.take(), std::nullopt});
  out.metadata[kPixelsPerPoint] = std::to_string(c.pixels_per_point);
  out.metadata[kFocalBaseline] = fmt::format("{}", c.focal_baseline_px_m);  // shortest text that reads back exactly
  return out;
}

class PointCloudDecoder final : public Decoder {
 public:
  std::vector<ChannelSpec> inputs() const override { return channels(""); }
  std::shared_ptr<const void> feed(std::size_t, std::span<const std::uint8_t> cdr, std::uint32_t,
                                   const ChannelMetadata& metadata) override {
    CdrReader r(cdr);
    auto cloud = std::make_shared<msg::PointCloud>();
    const Header h = read_header(r);
    cloud->stamp = h.stamp;
    cloud->frame = h.frame_id;
    const std::uint64_t height = r.u32(), width = r.u32();
    int offset[3] = {-1, -1, -1};
    const std::uint32_t fields = r.sequence_length(13);
    for (std::uint32_t i = 0; i < fields; ++i) {
      const std::string name = r.string();
      const std::uint32_t at = r.u32();
      const std::uint8_t type = r.u8();
      r.u32();  // count
      const int axis = name == "x" ? 0 : name == "y" ? 1 : name == "z" ? 2 : -1;
      if (axis >= 0 && type == kFloat32) offset[axis] = static_cast<int>(at);
    }
    if (r.boolean()) throw CdrError("a big-endian point cloud is not read here");
    const std::uint32_t step = r.u32();
    r.u32();  // row_step
    const std::vector<std::uint8_t> data = r.bytes();
    const bool dense = r.boolean();
    expect_end(r, "sensor_msgs/msg/PointCloud2");
    for (int axis = 0; axis < 3; ++axis)
      if (offset[axis] < 0 || static_cast<std::uint64_t>(offset[axis]) + 4 > step)
        throw CdrError("a point cloud without float32 x, y and z inside its point step");
    const std::uint64_t n = height * width;
    if (n * step > data.size())
      throw CdrError("point cloud data of " + std::to_string(data.size()) + " bytes cannot hold " + std::to_string(n) +
                     " points of " + std::to_string(step) + " bytes");
    auto points = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
    points->points.resize(n);
    for (std::uint64_t i = 0; i < n; ++i) {
      float xyz[3];
      for (int axis = 0; axis < 3; ++axis) std::memcpy(&xyz[axis], data.data() + i * step + offset[axis], 4);
      points->points[i] = pcl::PointXYZ(xyz[0], xyz[1], xyz[2]);
    }
    points->width = static_cast<std::uint32_t>(n);
    points->height = 1;
    points->is_dense = dense;
    cloud->points = points;
    if (auto it = metadata.find(kPixelsPerPoint); it != metadata.end()) {
      try {
        cloud->pixels_per_point = std::stoi(it->second);
      } catch (const std::exception&) {
        throw Error(std::string(kPixelsPerPoint) + " '" + it->second + "' in a channel's metadata is not a number");
      }
    }
    if (auto it = metadata.find(kFocalBaseline); it != metadata.end()) {
      char* end = nullptr;
      const double value = std::strtod(it->second.c_str(), &end);
      if (it->second.empty() || *end != '\0' || !std::isfinite(value) || value < 0.0)
        throw Error(std::string(kFocalBaseline) + " '" + it->second + "' in a channel's metadata is not a number >= 0");
      cloud->focal_baseline_px_m = value;
    }
    return cloud;
  }
};

}  // namespace point_cloud

TypeCodec point_cloud_codec() {
  using namespace point_cloud;
  return {MessageTraits<msg::PointCloud>::name, channels, encode,
          [] { return std::unique_ptr<Decoder>(std::make_unique<PointCloudDecoder>()); }};
}

}  // namespace kestrel::ros2::detail
