// kestrel.StereoFrame: /NODE/PORT/left and /right as sensor_msgs/msg/Image, each with its
// sensor_msgs/msg/CameraInfo (".../camera_info"), as ROS 2 stereo drivers publish them. The
// calibration goes in the camera infos' K and P (the right P holds Tx = -fx * baseline), the
// frame index in the MCAP sequence of each message; replay pairs the four again by stamp. The
// camera's mount travels in the channels' metadata and, for viewers, on /tf (parent -> "camera").
#include <fmt/format.h>

#include <cmath>
#include <cstring>
#include <kestrel/messages/stereo_frame.hpp>
#include <limits>
#include <map>
#include <opencv2/core.hpp>
#include <sstream>

#include "fields.hpp"

namespace kestrel::ros2::detail {

// Named, so that the codecs, which use the same names for their parts, can share a translation unit.
namespace stereo_frame {

enum Part : std::size_t { kLeft, kRight, kLeftInfo, kRightInfo, kParts, kTf = kParts };

const char* const kMount = "kestrel.mount";  // "PARENT x y z qw qx qy qz"

std::vector<ChannelSpec> parts(const std::string& topic) {
  return {{topic + "/left", "sensor_msgs/msg/Image", false},
          {topic + "/right", "sensor_msgs/msg/Image", false},
          {topic + "/left/camera_info", "sensor_msgs/msg/CameraInfo", false},
          {topic + "/right/camera_info", "sensor_msgs/msg/CameraInfo", false}};
}

std::vector<ChannelSpec> channels(const std::string& topic) {
  std::vector<ChannelSpec> out = parts(topic);
  out.push_back({"/tf", "tf2_msgs/msg/TFMessage", true});
  return out;
}

// Shortest decimal forms that read back to the same doubles.
std::string mount_text(const msg::CameraMount& m) {
  const auto& p = m.position;
  const auto& q = m.orientation;
  return fmt::format("{} {} {} {} {} {} {} {}", m.parent_frame, p.x(), p.y(), p.z(), q.w(), q.x(), q.y(), q.z());
}

msg::CameraMount read_mount(const std::string& text) {
  std::istringstream in(text);
  in.imbue(std::locale::classic());
  msg::CameraMount m;
  double v[7];
  in >> m.parent_frame;
  for (double& x : v) in >> x;
  std::string rest;
  if (!in || (in >> rest, !rest.empty()) || m.parent_frame.empty())
    throw Error(std::string(kMount) + " '" + text + "' in a channel's metadata is not 'PARENT x y z qw qx qy qz'");
  m.position = {v[0], v[1], v[2]};
  m.orientation = Eigen::Quaterniond(v[3], v[4], v[5], v[6]);
  return m;
}

const char* encoding_of(const cv::Mat& image) {
  if (image.type() == CV_8UC1) return "mono8";
  if (image.type() == CV_8UC3) return "bgr8";
  throw Error("a stereo image of OpenCV type " + std::to_string(image.type()) +
              " has no ROS 2 encoding here (CV_8UC1 as mono8 and CV_8UC3 as bgr8 do)");
}

std::vector<std::uint8_t> image(const cv::Mat& m, Time stamp) {
  CdrWriter w;
  write_header(w, stamp, "camera");
  w.u32(static_cast<std::uint32_t>(m.rows));
  w.u32(static_cast<std::uint32_t>(m.cols));
  w.string(encoding_of(m));
  w.u8(0);  // little-endian
  const std::size_t row_bytes = static_cast<std::size_t>(m.cols) * m.elemSize();
  w.u32(static_cast<std::uint32_t>(row_bytes));
  std::vector<std::uint8_t> data(row_bytes * static_cast<std::size_t>(m.rows));
  for (int r = 0; r < m.rows; ++r)
    std::memcpy(data.data() + row_bytes * static_cast<std::size_t>(r), m.ptr(r), row_bytes);
  w.bytes(data);
  return w.take();
}

// The right camera's P[3] = -fx * b, nudged by ulps until -P[3] / fx gives back b exactly, so that
// any reader's plain formula recovers the very baseline (the depth of every pixel depends on it).
double right_tx(double fx, double baseline) {
  double tx = -fx * baseline;
  for (int step = 0; step < 64 && -tx / fx != baseline; ++step)
    tx = std::nextafter(
        tx, -tx / fx < baseline ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity());
  return tx;
}

std::vector<std::uint8_t> camera_info(const msg::StereoCalibration& c, Time stamp, bool right) {
  CdrWriter w;
  write_header(w, stamp, "camera");
  w.u32(static_cast<std::uint32_t>(c.height));
  w.u32(static_cast<std::uint32_t>(c.width));
  w.string("plumb_bob");
  const double d[5] = {0, 0, 0, 0, 0};  // rectified images: no distortion left
  w.sequence_length(5);
  for (double v : d) w.f64(v);
  const double k[9] = {c.fx, 0, c.cx, 0, c.fy, c.cy, 0, 0, 1};
  for (double v : k) w.f64(v);
  const double r[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  for (double v : r) w.f64(v);
  const double p[12] = {c.fx, 0, c.cx, right ? right_tx(c.fx, c.baseline_m) : 0.0, 0, c.fy, c.cy, 0, 0, 0, 1, 0};
  for (double v : p) w.f64(v);
  w.u32(0);  // binning
  w.u32(0);
  for (int i = 0; i < 4; ++i) w.u32(0);  // roi: the whole image
  w.boolean(false);
  return w.take();
}

Encoded encode(const void* message, const std::string&) {
  const auto& f = *static_cast<const msg::StereoFrame*>(message);
  if (f.frame_index > std::numeric_limits<std::uint32_t>::max())
    throw Error("frame_index " + std::to_string(f.frame_index) + " does not fit an MCAP sequence (32 bits)");
  if (f.left.size() != f.right.size() || f.left.type() != f.right.type())
    throw Error("a stereo frame's images differ in size or type");
  const auto seq = static_cast<std::uint32_t>(f.frame_index);
  Encoded out;
  out.messages.push_back({kLeft, image(f.left, f.stamp), seq});
  out.messages.push_back({kRight, image(f.right, f.stamp), seq});
  out.messages.push_back({kLeftInfo, camera_info(f.calibration, f.stamp, false), seq});
  out.messages.push_back({kRightInfo, camera_info(f.calibration, f.stamp, true), seq});
  out.messages.push_back(
      {kTf, tf_message(f.stamp, f.mount.parent_frame, "camera", f.mount.position, f.mount.orientation), std::nullopt});
  out.metadata[kMount] = mount_text(f.mount);
  return out;
}

cv::Mat read_image(CdrReader& r, Time& stamp) {
  stamp = read_header(r).stamp;
  const std::uint32_t height = r.u32(), width = r.u32();
  const std::string encoding = r.string();
  r.u8();  // is_bigendian: irrelevant for 8-bit pixels
  const std::uint32_t step = r.u32();
  const std::vector<std::uint8_t> data = r.bytes();
  int type = 0;
  if (encoding == "mono8" || encoding == "8UC1")
    type = CV_8UC1;
  else if (encoding == "bgr8" || encoding == "rgb8" || encoding == "8UC3")
    type = CV_8UC3;
  else
    throw CdrError("image encoding '" + encoding + "' is not read here (mono8, bgr8 and rgb8 are)");
  const std::size_t row_bytes = static_cast<std::size_t>(width) * (type == CV_8UC1 ? 1 : 3);
  if (height > 1u << 15 || width > 1u << 15)
    throw CdrError("an image of " + std::to_string(width) + "x" + std::to_string(height));
  if (step < row_bytes || data.size() < static_cast<std::size_t>(step) * height)
    throw CdrError("image data of " + std::to_string(data.size()) + " bytes cannot hold " + std::to_string(height) +
                   " rows of step " + std::to_string(step));
  cv::Mat m(static_cast<int>(height), static_cast<int>(width), type);
  for (std::uint32_t row = 0; row < height; ++row)
    std::memcpy(m.ptr(static_cast<int>(row)), data.data() + static_cast<std::size_t>(step) * row, row_bytes);
  if (encoding == "rgb8") {  // kestrel's colour images are BGR, as OpenCV's
    cv::Mat bgr(m.size(), m.type());
    const int from_to[] = {0, 2, 1, 1, 2, 0};
    cv::mixChannels(&m, 1, &bgr, 1, from_to, 3);
    return bgr;
  }
  return m;
}

struct Info {
  int width = 0, height = 0;
  double p[12] = {};
};

Info read_info(CdrReader& r, Time& stamp) {
  stamp = read_header(r).stamp;
  Info info;
  info.height = static_cast<int>(r.u32());
  info.width = static_cast<int>(r.u32());
  r.string();
  const std::uint32_t nd = r.sequence_length(8);
  for (std::uint32_t i = 0; i < nd; ++i) r.f64();
  for (int i = 0; i < 18; ++i) r.f64();  // k, r
  for (double& v : info.p) v = r.f64();
  for (int i = 0; i < 6; ++i) r.u32();  // binning, roi
  r.boolean();
  return info;
}

class StereoFrameDecoder final : public Decoder {
 public:
  std::vector<ChannelSpec> inputs() const override { return parts(""); }
  std::shared_ptr<const void> feed(std::size_t input, std::span<const std::uint8_t> cdr, std::uint32_t sequence,
                                   const ChannelMetadata& metadata) override {
    if (input >= kParts) throw Error("a stereo frame has no input " + std::to_string(input));
    CdrReader r(cdr);
    Time stamp{0};
    if (input == kLeft || input == kRight) {
      cv::Mat m = read_image(r, stamp);
      expect_end(r, "sensor_msgs/msg/Image");
      Parts& p = pending(stamp);
      (input == kLeft ? p.left : p.right) = std::move(m);
      p.have[input] = true;
      p.sequence = sequence;
      if (input == kLeft)
        if (auto it = metadata.find(kMount); it != metadata.end()) p.mount = read_mount(it->second);
    } else {
      Info info = read_info(r, stamp);
      expect_end(r, "sensor_msgs/msg/CameraInfo");
      Parts& p = pending(stamp);
      (input == kLeftInfo ? p.left_info : p.right_info) = info;
      p.have[input] = true;
    }
    auto it = pending_.find(stamp);
    if (!(it->second.have[0] && it->second.have[1] && it->second.have[2] && it->second.have[3])) return nullptr;
    auto frame = std::make_shared<msg::StereoFrame>();
    const Parts& p = it->second;
    frame->stamp = stamp;
    frame->frame_index = p.sequence;
    frame->left = p.left;
    frame->right = p.right;
    frame->calibration.width = p.left_info.width;
    frame->calibration.height = p.left_info.height;
    frame->calibration.fx = p.left_info.p[0];
    frame->calibration.fy = p.left_info.p[5];
    frame->calibration.cx = p.left_info.p[2];
    frame->calibration.cy = p.left_info.p[6];
    frame->calibration.baseline_m = p.right_info.p[0] != 0 ? -p.right_info.p[3] / p.right_info.p[0] : 0.0;
    frame->mount = p.mount;
    pending_.erase(it);
    return frame;
  }
  std::uint64_t unpaired() const override { return dropped_ + pending_.size(); }

 private:
  struct Parts {
    bool have[kParts] = {false, false, false, false};
    cv::Mat left, right;
    Info left_info, right_info;
    std::uint32_t sequence = 0;
    msg::CameraMount mount;  // a bag from another driver has none: the default level camera
  };
  // The parts of a frame arrive together in a kestrel file; in another bag they may interleave
  // with a few frames' worth of others. Older incomplete frames are dropped and counted.
  Parts& pending(Time stamp) {
    while (pending_.size() >= kMaxPending && !pending_.count(stamp)) {
      pending_.erase(pending_.begin());
      ++dropped_;
    }
    return pending_[stamp];
  }
  static constexpr std::size_t kMaxPending = 16;
  std::map<Time, Parts> pending_;
  std::uint64_t dropped_ = 0;
};

}  // namespace stereo_frame

TypeCodec stereo_frame_codec() {
  using namespace stereo_frame;
  return {MessageTraits<msg::StereoFrame>::name, channels, encode,
          [] { return std::unique_ptr<Decoder>(std::make_unique<StereoFrameDecoder>()); }};
}

}  // namespace kestrel::ros2::detail
