#pragma once
// A V4L2 capture device in memory, behind the V4l2Io interface: it answers the ioctls a capture
// makes (formats, rates, buffers, controls, streaming) and delivers the frames a test scripts,
// each possibly short, flagged bad, late, or followed by the device vanishing.
#include <linux/videodev2.h>
#include <sys/mman.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "kestrel/v4l2/v4l2_io.hpp"

namespace kestrel::testing {

class FakeV4l2 final : public v4l2::V4l2Io {
 public:
  struct Mode {
    int width, height;
    std::vector<int> fps;
  };
  struct ScriptedFrame {
    ScriptedFrame(std::vector<std::uint8_t> bytes, std::chrono::milliseconds delay = {}, bool flagged = false,
                  std::optional<std::size_t> used = {}, std::uint32_t step = 1)
        : data(std::move(bytes)), after(delay), error_flag(flagged), bytesused(used), sequence_step(step) {}
    std::vector<std::uint8_t> data;
    std::chrono::milliseconds after;       ///< ready this long after the capture starts waiting for it
    bool error_flag;                       ///< the driver flags it V4L2_BUF_FLAG_ERROR
    std::optional<std::size_t> bytesused;  ///< default: data.size()
    std::uint32_t sequence_step;           ///< more than 1: frames lost before this one
  };

  std::string path = "/dev/video-fake";
  std::string card = "oCamS-1CGN-U";
  std::vector<Mode> modes = {{1280, 960, {45, 30, 25, 20, 15, 10}}, {640, 480, {45, 30, 25, 20, 15, 10}}};
  std::map<std::uint32_t, v4l2_queryctrl> controls;
  std::map<std::uint32_t, std::int32_t> values;
  std::deque<ScriptedFrame> frames;
  bool present = true;             ///< open() finds the device
  bool unplug_when_empty = false;  ///< once the script has played, the device vanishes
  int opens = 0;

  FakeV4l2() {
    add_control(V4L2_CID_EXPOSURE_ABSOLUTE, "Exposure Time, Absolute", 1, 625, 100);
    add_control(V4L2_CID_GAIN, "Gain", 0, 255, 32);
    add_control(V4L2_CID_RED_BALANCE, "Red Balance", 0, 250, 150);
    add_control(V4L2_CID_BLUE_BALANCE, "Blue Balance", 0, 250, 200);
    add_control(V4L2_CID_EXPOSURE_AUTO, "Auto Exposure", 0, 3, 3);
  }
  void add_control(std::uint32_t id, const char* name, int min, int max, int def) {
    v4l2_queryctrl q{};
    q.id = id;
    std::strncpy(reinterpret_cast<char*>(q.name), name, sizeof q.name - 1);
    q.minimum = min;
    q.maximum = max;
    q.step = 1;
    q.default_value = def;
    controls[id] = q;
    values[id] = def;
  }
  bool streaming() const { return streaming_; }

  int open(const char* p, int) override {
    if (!present || path != p) return fail(ENOENT);
    ++opens;
    gone_ = false;
    return 7;
  }
  int close(int) override { return 0; }
  void* mmap(std::size_t length, int, off_t offset) override {
    const auto i = static_cast<std::size_t>(offset) / kStride;
    if (i >= buffers_.size() || length > buffers_[i].memory.size()) return MAP_FAILED;
    return buffers_[i].memory.data();
  }
  int munmap(void*, std::size_t) override { return 0; }

  int poll(pollfd* fds, nfds_t, int timeout_ms) override {
    fds[0].revents = 0;
    if (gone_) return fds[0].revents = POLLERR, 1;
    if (frames.empty()) {
      if (unplug_when_empty && streaming_) {
        gone_ = true;
        present = false;
        return fds[0].revents = POLLERR, 1;
      }
      sleep(timeout_ms);
      return 0;
    }
    const auto now = std::chrono::steady_clock::now();
    if (!waiting_since_) waiting_since_ = now;
    const auto ready_at = *waiting_since_ + frames.front().after;
    if (ready_at > now) {
      const auto wait = std::chrono::duration_cast<std::chrono::milliseconds>(ready_at - now).count() + 1;
      sleep(static_cast<int>(std::min<long long>(wait, timeout_ms)));
      if (wait > timeout_ms) return 0;
    }
    return fds[0].revents = POLLIN, 1;
  }

  int ioctl(int, unsigned long request, void* arg) override {
    if (gone_) return fail(ENODEV);
    switch (request) {
      case VIDIOC_QUERYCAP: {
        auto* c = static_cast<v4l2_capability*>(arg);
        *c = {};
        std::strncpy(reinterpret_cast<char*>(c->card), card.c_str(), sizeof c->card - 1);
        std::strncpy(reinterpret_cast<char*>(c->driver), "uvcvideo", sizeof c->driver - 1);
        std::strncpy(reinterpret_cast<char*>(c->bus_info), "usb-0000:00:14.0-1", sizeof c->bus_info - 1);
        c->capabilities = V4L2_CAP_VIDEO_CAPTURE | V4L2_CAP_STREAMING;
        return 0;
      }
      case VIDIOC_ENUM_FMT: {
        auto* f = static_cast<v4l2_fmtdesc*>(arg);
        if (f->index > 0) return fail(EINVAL);
        f->pixelformat = V4L2_PIX_FMT_YUYV;
        return 0;
      }
      case VIDIOC_ENUM_FRAMESIZES: {
        auto* s = static_cast<v4l2_frmsizeenum*>(arg);
        if (s->index >= modes.size()) return fail(EINVAL);
        s->type = V4L2_FRMSIZE_TYPE_DISCRETE;
        s->discrete = {static_cast<__u32>(modes[s->index].width), static_cast<__u32>(modes[s->index].height)};
        return 0;
      }
      case VIDIOC_ENUM_FRAMEINTERVALS: {
        auto* i = static_cast<v4l2_frmivalenum*>(arg);
        const Mode* m = find(static_cast<int>(i->width), static_cast<int>(i->height));
        if (!m || i->index >= m->fps.size()) return fail(EINVAL);
        i->type = V4L2_FRMIVAL_TYPE_DISCRETE;
        i->discrete = {1, static_cast<__u32>(m->fps[i->index])};
        return 0;
      }
      case VIDIOC_S_FMT: {  // as drivers do: what it cannot do becomes what it can
        auto& pix = static_cast<v4l2_format*>(arg)->fmt.pix;
        const Mode* m = find(static_cast<int>(pix.width), static_cast<int>(pix.height));
        if (!m) m = &modes.front();
        pix.width = static_cast<__u32>(width_ = m->width);
        pix.height = static_cast<__u32>(height_ = m->height);
        pix.pixelformat = V4L2_PIX_FMT_YUYV;
        pix.sizeimage = pix.width * pix.height * 2;
        return 0;
      }
      case VIDIOC_S_PARM: {
        auto& tpf = static_cast<v4l2_streamparm*>(arg)->parm.capture.timeperframe;
        const Mode* m = find(width_, height_);
        const int want = tpf.numerator ? static_cast<int>(tpf.denominator / tpf.numerator) : 0;
        fps_ = m && std::find(m->fps.begin(), m->fps.end(), want) != m->fps.end() ? want : m->fps.front();
        tpf = {1, static_cast<__u32>(fps_)};
        return 0;
      }
      case VIDIOC_REQBUFS: {
        auto* r = static_cast<v4l2_requestbuffers*>(arg);
        buffers_.assign(r->count,
                        Buffer{std::vector<std::uint8_t>(static_cast<std::size_t>(width_ * height_ * 2)), false});
        return 0;
      }
      case VIDIOC_QUERYBUF: {
        auto* b = static_cast<v4l2_buffer*>(arg);
        if (b->index >= buffers_.size()) return fail(EINVAL);
        b->length = static_cast<__u32>(buffers_[b->index].memory.size());
        b->m.offset = static_cast<__u32>(b->index * kStride);
        return 0;
      }
      case VIDIOC_QBUF: {
        auto* b = static_cast<v4l2_buffer*>(arg);
        if (b->index >= buffers_.size() || buffers_[b->index].queued) return fail(EINVAL);
        buffers_[b->index].queued = true;
        return 0;
      }
      case VIDIOC_DQBUF: {
        auto* b = static_cast<v4l2_buffer*>(arg);
        std::size_t i = 0;
        while (i < buffers_.size() && !buffers_[i].queued) ++i;
        if (frames.empty() || i == buffers_.size()) return fail(EAGAIN);
        ScriptedFrame f = std::move(frames.front());
        frames.pop_front();
        waiting_since_.reset();
        Buffer& buffer = buffers_[i];
        buffer.queued = false;
        std::memcpy(buffer.memory.data(), f.data.data(), std::min(f.data.size(), buffer.memory.size()));
        sequence_ += f.sequence_step;
        b->index = static_cast<__u32>(i);
        b->bytesused = static_cast<__u32>(f.bytesused.value_or(f.data.size()));
        b->flags = f.error_flag ? V4L2_BUF_FLAG_ERROR : 0;
        b->sequence = sequence_;
        return 0;
      }
      case VIDIOC_STREAMON:
        streaming_ = true;
        return 0;
      case VIDIOC_STREAMOFF:
        streaming_ = false;
        return 0;
      case VIDIOC_QUERYCTRL: {
        auto* q = static_cast<v4l2_queryctrl*>(arg);
        const auto it = controls.find(q->id);
        if (it == controls.end()) return fail(EINVAL);
        *q = it->second;
        return 0;
      }
      case VIDIOC_S_CTRL: {
        auto* c = static_cast<v4l2_control*>(arg);
        if (!controls.count(c->id)) return fail(EINVAL);
        values[c->id] = c->value;
        return 0;
      }
      case VIDIOC_G_CTRL: {
        auto* c = static_cast<v4l2_control*>(arg);
        if (!values.count(c->id)) return fail(EINVAL);
        c->value = values[c->id];
        return 0;
      }
      default:
        return fail(ENOTTY);
    }
  }

 private:
  static constexpr std::size_t kStride = 1 << 22;  // mapping offsets: one per buffer
  struct Buffer {
    std::vector<std::uint8_t> memory;
    bool queued = false;
  };
  static int fail(int e) {
    errno = e;
    return -1;
  }
  static void sleep(int ms) {
    if (ms > 0) std::this_thread::sleep_for(std::chrono::milliseconds(ms));
  }
  const Mode* find(int w, int h) const {
    for (const auto& m : modes)
      if (m.width == w && m.height == h) return &m;
    return nullptr;
  }
  std::vector<Buffer> buffers_;
  bool streaming_ = false, gone_ = false;
  int width_ = 0, height_ = 0, fps_ = 0;
  std::uint32_t sequence_ = 0;
  std::optional<std::chrono::steady_clock::time_point> waiting_since_;
};

}  // namespace kestrel::testing
