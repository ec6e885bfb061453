#include "kestrel/v4l2/v4l2_camera.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <linux/videodev2.h>
#include <sys/mman.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>

namespace kestrel::v4l2 {

namespace {

std::string text_of(const __u8* s, std::size_t n) {
  return std::string(reinterpret_cast<const char*>(s), strnlen(reinterpret_cast<const char*>(s), n));
}

// errno values that mean the device is no longer there.
bool gone(int e) { return e == ENODEV || e == ENXIO || e == ENOENT || e == EIO; }

}  // namespace

std::string fourcc_text(std::uint32_t f) {
  std::string s;
  for (int i = 0; i < 4; ++i) {
    const char c = static_cast<char>((f >> (8 * i)) & 0xff);
    s += (c >= 0x20 && c < 0x7f) ? c : '?';
  }
  return s;
}

V4l2Camera::V4l2Camera(V4l2Io& io, std::string path) : io_(io), path_(std::move(path)) {
  fd_ = io_.open(path_.c_str(), O_RDWR | O_NONBLOCK);
  if (fd_ < 0) {
    const int e = errno;
    if (e == EACCES) throw Error(path_ + ": permission denied (docs/hardware.md: the udev rule, or the video group)");
    throw DeviceLost(path_ + ": " + std::strerror(e));
  }
  v4l2_capability cap{};
  if (io_.ioctl(fd_, VIDIOC_QUERYCAP, &cap) != 0) {
    const int e = errno;
    io_.close(fd_);
    fd_ = -1;
    throw Error(path_ + " is not a V4L2 device: " + std::strerror(e));
  }
  const std::uint32_t caps = (cap.capabilities & V4L2_CAP_DEVICE_CAPS) ? cap.device_caps : cap.capabilities;
  if (!(caps & V4L2_CAP_VIDEO_CAPTURE) || !(caps & V4L2_CAP_STREAMING)) {
    io_.close(fd_);
    fd_ = -1;
    throw Error(path_ + " (" + text_of(cap.card, sizeof cap.card) + ") is not a streaming capture device");
  }
}

V4l2Camera::~V4l2Camera() {
  stop();
  if (fd_ >= 0) io_.close(fd_);
}

void V4l2Camera::fail(const std::string& what) const {
  const int e = errno;
  if (gone(e)) throw DeviceLost(path_ + ": " + what + ": " + std::strerror(e));
  throw Error(path_ + ": " + what + ": " + std::strerror(e));
}

DeviceInfo V4l2Camera::describe() const {
  DeviceInfo info;
  info.path = path_;
  v4l2_capability cap{};
  if (io_.ioctl(fd_, VIDIOC_QUERYCAP, &cap) == 0) {
    info.card = text_of(cap.card, sizeof cap.card);
    info.driver = text_of(cap.driver, sizeof cap.driver);
    info.bus = text_of(cap.bus_info, sizeof cap.bus_info);
  }
  for (__u32 fi = 0; fi < 64; ++fi) {
    v4l2_fmtdesc fmt{};
    fmt.index = fi;
    fmt.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    if (io_.ioctl(fd_, VIDIOC_ENUM_FMT, &fmt) != 0) break;
    for (__u32 si = 0; si < 64; ++si) {
      v4l2_frmsizeenum size{};
      size.index = si;
      size.pixel_format = fmt.pixelformat;
      if (io_.ioctl(fd_, VIDIOC_ENUM_FRAMESIZES, &size) != 0 || size.type != V4L2_FRMSIZE_TYPE_DISCRETE) break;
      DeviceInfo::Mode mode{
          fmt.pixelformat, static_cast<int>(size.discrete.width), static_cast<int>(size.discrete.height), {}};
      for (__u32 ii = 0; ii < 64; ++ii) {
        v4l2_frmivalenum interval{};
        interval.index = ii;
        interval.pixel_format = fmt.pixelformat;
        interval.width = size.discrete.width;
        interval.height = size.discrete.height;
        if (io_.ioctl(fd_, VIDIOC_ENUM_FRAMEINTERVALS, &interval) != 0 || interval.type != V4L2_FRMIVAL_TYPE_DISCRETE ||
            interval.discrete.numerator == 0)
          break;
        mode.fps.push_back(static_cast<double>(interval.discrete.denominator) / interval.discrete.numerator);
      }
      info.modes.push_back(mode);
    }
  }
  return info;
}

void V4l2Camera::start(const CaptureFormat& format) {
  stop();
  auto offered = [&] {
    std::string s;
    for (const auto& m : describe().modes) {
      s += "\n  " + fourcc_text(m.fourcc) + " " + std::to_string(m.width) + "x" + std::to_string(m.height) + " @";
      for (double f : m.fps) s += " " + std::to_string(static_cast<int>(std::lround(f)));
    }
    return s.empty() ? std::string(" (the device lists none)") : ": it offers" + s;
  };
  v4l2_format fmt{};
  fmt.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  fmt.fmt.pix.width = static_cast<__u32>(format.width);
  fmt.fmt.pix.height = static_cast<__u32>(format.height);
  fmt.fmt.pix.pixelformat = format.fourcc;
  fmt.fmt.pix.field = V4L2_FIELD_NONE;
  if (io_.ioctl(fd_, VIDIOC_S_FMT, &fmt) != 0) fail("setting the format");
  // A driver adjusts what it cannot do instead of refusing it: check what it chose.
  if (fmt.fmt.pix.width != static_cast<__u32>(format.width) ||
      fmt.fmt.pix.height != static_cast<__u32>(format.height) || fmt.fmt.pix.pixelformat != format.fourcc)
    throw Error(path_ + " does not stream " + fourcc_text(format.fourcc) + " " + std::to_string(format.width) + "x" +
                std::to_string(format.height) + offered());
  frame_bytes_ = static_cast<std::size_t>(format.width) * static_cast<std::size_t>(format.height) * 2u;
  v4l2_streamparm parm{};
  parm.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  parm.parm.capture.timeperframe.numerator = 1;
  parm.parm.capture.timeperframe.denominator = static_cast<__u32>(format.fps);
  if (io_.ioctl(fd_, VIDIOC_S_PARM, &parm) != 0) fail("setting the frame rate");
  const auto& tpf = parm.parm.capture.timeperframe;
  if (tpf.numerator == 0 || std::abs(static_cast<double>(tpf.denominator) / tpf.numerator - format.fps) > 0.5)
    throw Error(path_ + " does not stream " + std::to_string(format.width) + "x" + std::to_string(format.height) +
                " at " + std::to_string(format.fps) + " FPS" + offered());

  v4l2_requestbuffers req{};
  req.count = static_cast<__u32>(format.buffers);
  req.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  req.memory = V4L2_MEMORY_MMAP;
  if (io_.ioctl(fd_, VIDIOC_REQBUFS, &req) != 0) fail("asking for buffers");
  if (req.count < 2) throw Error(path_ + " gave " + std::to_string(req.count) + " buffer(s); streaming needs 2");
  for (__u32 i = 0; i < req.count; ++i) {
    v4l2_buffer b{};
    b.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    b.memory = V4L2_MEMORY_MMAP;
    b.index = i;
    if (io_.ioctl(fd_, VIDIOC_QUERYBUF, &b) != 0) fail("querying a buffer");
    void* p = io_.mmap(b.length, fd_, static_cast<off_t>(b.m.offset));
    if (p == MAP_FAILED) fail("mapping a buffer");
    buffers_.push_back({p, b.length});
    if (b.length < frame_bytes_)
      throw Error(path_ + ": a buffer of " + std::to_string(b.length) + " bytes cannot hold a frame of " +
                  std::to_string(frame_bytes_));
    if (io_.ioctl(fd_, VIDIOC_QBUF, &b) != 0) fail("queueing a buffer");
  }
  v4l2_buf_type type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  if (io_.ioctl(fd_, VIDIOC_STREAMON, &type) != 0) fail("starting the stream");
  streaming_ = true;
  last_sequence_.reset();
}

void V4l2Camera::requeue_held() {
  if (!held_) return;
  v4l2_buffer b{};
  b.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  b.memory = V4L2_MEMORY_MMAP;
  b.index = *held_;
  held_.reset();
  if (io_.ioctl(fd_, VIDIOC_QBUF, &b) != 0) fail("queueing a buffer again");
}

std::optional<CapturedFrame> V4l2Camera::next(std::chrono::milliseconds timeout) {
  if (!streaming_) throw Error(path_ + ": next() before start()");
  requeue_held();
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now()).count();
    pollfd p{fd_, POLLIN, 0};
    const int ready = io_.poll(&p, 1, static_cast<int>(std::max<long long>(0, left)));
    if (ready < 0) {
      if (errno == EINTR) continue;
      fail("waiting for a frame");
    }
    if (p.revents & (POLLERR | POLLHUP | POLLNVAL)) {
      errno = ENODEV;
      fail("waiting for a frame");
    }
    if (ready == 0 || !(p.revents & POLLIN)) {
      if (left <= 0) return std::nullopt;
      continue;
    }
    v4l2_buffer b{};
    b.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    b.memory = V4L2_MEMORY_MMAP;
    if (io_.ioctl(fd_, VIDIOC_DQBUF, &b) != 0) {
      if (errno == EAGAIN) continue;
      fail("taking a frame");
    }
    if (b.index >= buffers_.size()) throw Error(path_ + ": the driver returned buffer " + std::to_string(b.index));
    held_ = b.index;
    if (last_sequence_ && b.sequence > *last_sequence_ + 1) counters_.sequence_gaps += b.sequence - *last_sequence_ - 1;
    last_sequence_ = b.sequence;
    if (b.flags & V4L2_BUF_FLAG_ERROR) {
      ++counters_.error_frames;
      requeue_held();
      continue;
    }
    if (b.bytesused != frame_bytes_) {
      ++counters_.short_frames;
      requeue_held();
      continue;
    }
    ++counters_.frames;
    return CapturedFrame{{static_cast<const std::uint8_t*>(buffers_[b.index].start), frame_bytes_}, b.sequence};
  }
}

void V4l2Camera::stop() {
  if (fd_ < 0) return;
  if (streaming_) {
    v4l2_buf_type type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    io_.ioctl(fd_, VIDIOC_STREAMOFF, &type);  // a device already gone cannot be stopped: nothing to do
    streaming_ = false;
  }
  held_.reset();
  for (const auto& b : buffers_) io_.munmap(b.start, b.length);
  buffers_.clear();
  if (frame_bytes_ > 0) {
    v4l2_requestbuffers req{};
    req.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    req.memory = V4L2_MEMORY_MMAP;
    io_.ioctl(fd_, VIDIOC_REQBUFS, &req);  // count 0 frees them
  }
}

std::optional<V4l2Camera::ControlRange> V4l2Camera::control_range(std::uint32_t id) const {
  v4l2_queryctrl q{};
  q.id = id;
  if (io_.ioctl(fd_, VIDIOC_QUERYCTRL, &q) != 0 || (q.flags & V4L2_CTRL_FLAG_DISABLED)) return std::nullopt;
  return ControlRange{q.minimum, q.maximum, q.step, q.default_value, text_of(q.name, sizeof q.name)};
}

void V4l2Camera::set_control(std::uint32_t id, std::int32_t value) {
  const auto range = control_range(id);
  if (!range) throw Error(fmt::format("{} has no control {:#x}", path_, id));
  if (value < range->minimum || value > range->maximum)
    throw Error(path_ + ": " + range->name + " " + std::to_string(value) + " is outside [" +
                std::to_string(range->minimum) + ", " + std::to_string(range->maximum) + "]");
  v4l2_control c{id, value};
  if (io_.ioctl(fd_, VIDIOC_S_CTRL, &c) != 0) fail("setting " + range->name);
}

std::int32_t V4l2Camera::control(std::uint32_t id) const {
  v4l2_control c{id, 0};
  if (io_.ioctl(fd_, VIDIOC_G_CTRL, &c) != 0) fail("reading control " + std::to_string(id));
  return c.value;
}

std::vector<DeviceInfo> list_video_devices(V4l2Io& io) {
  std::vector<std::string> paths;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator("/dev", ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("video", 0) == 0) paths.push_back(entry.path().string());
  }
  std::sort(paths.begin(), paths.end());
  std::vector<DeviceInfo> out;
  for (const auto& path : paths) {
    try {
      out.push_back(V4l2Camera(io, path).describe());
    } catch (const Error&) {
      // metadata nodes and devices that are not capture ones
    }
  }
  return out;
}

}  // namespace kestrel::v4l2
