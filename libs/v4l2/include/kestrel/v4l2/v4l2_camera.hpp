#pragma once
// A V4L2 capture device streaming through memory-mapped buffers: the format and frame rate set
// and checked, the buffers queued, each frame waited for with a timeout, checked for its size and
// error flag, and handed back to the driver when the next is asked for. All its system calls go
// through a V4l2Io, so that tests drive it with a fake device.
#include <chrono>
#include <cstdint>
#include <kestrel/error.hpp>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "kestrel/v4l2/v4l2_io.hpp"

namespace kestrel::v4l2 {

/// The device is gone (unplugged, or its driver unbound): reopen it once it is back.
class DeviceLost : public Error {
 public:
  using Error::Error;
};

struct CaptureFormat {
  int width = 640;
  int height = 480;
  int fps = 30;
  std::uint32_t fourcc = 0x56595559;  ///< 'YUYV', as the oCamS announces its pairs
  int buffers = 4;
};

/// One frame, valid until the next call to V4l2Camera::next() or stop().
struct CapturedFrame {
  std::span<const std::uint8_t> data;
  std::uint32_t sequence = 0;  ///< the driver's count: a gap is frames lost before us
};

/// Why a frame was not returned.
struct CaptureCounters {
  std::uint64_t frames = 0;
  std::uint64_t short_frames = 0;   ///< bytesused other than the frame's size
  std::uint64_t error_frames = 0;   ///< flagged V4L2_BUF_FLAG_ERROR by the driver
  std::uint64_t sequence_gaps = 0;  ///< frames the driver's sequence says were lost
};

/// What a device says of itself, for `kestrel devices` and errors.
struct DeviceInfo {
  std::string path;
  std::string card;  ///< "oCamS-1CGN-U"
  std::string driver;
  std::string bus;
  struct Mode {
    std::uint32_t fourcc = 0;
    int width = 0, height = 0;
    std::vector<double> fps;
  };
  std::vector<Mode> modes;
};

/// "YUYV".
std::string fourcc_text(std::uint32_t fourcc);

class V4l2Camera {
 public:
  /// Opens the device. Throws DeviceLost if it is not there, Error if it is not a streaming
  /// capture device.
  V4l2Camera(V4l2Io& io, std::string path);
  ~V4l2Camera();
  V4l2Camera(const V4l2Camera&) = delete;
  V4l2Camera& operator=(const V4l2Camera&) = delete;

  /// The device's name, driver, bus and the formats, sizes and rates it offers.
  DeviceInfo describe() const;
  /// Sets the format and frame rate, maps the buffers and starts streaming. Throws Error naming
  /// what the device offers when it does not take the format or the rate.
  void start(const CaptureFormat& format);
  /// The next frame whose size and flags are right, waiting at most `timeout` for it; nullopt
  /// if none came in time. Bad buffers are counted and skipped. Throws DeviceLost if the device
  /// went away.
  std::optional<CapturedFrame> next(std::chrono::milliseconds timeout);
  /// Stops streaming and unmaps the buffers; start() may follow again.
  void stop();

  /// A control's value range, or nullopt if the device has no such control.
  struct ControlRange {
    std::int32_t minimum = 0, maximum = 0, step = 1, default_value = 0;
    std::string name;
  };
  std::optional<ControlRange> control_range(std::uint32_t id) const;
  /// Sets a control; throws Error naming the control and its range when it refuses the value.
  void set_control(std::uint32_t id, std::int32_t value);
  std::int32_t control(std::uint32_t id) const;

  const CaptureCounters& counters() const { return counters_; }
  const std::string& path() const { return path_; }

 private:
  void requeue_held();
  [[noreturn]] void fail(const std::string& what) const;

  V4l2Io& io_;
  std::string path_;
  int fd_ = -1;
  struct Buffer {
    void* start = nullptr;
    std::size_t length = 0;
  };
  std::vector<Buffer> buffers_;
  std::size_t frame_bytes_ = 0;
  std::optional<std::uint32_t> held_;  // the buffer the last frame lives in
  std::optional<std::uint32_t> last_sequence_;
  bool streaming_ = false;
  CaptureCounters counters_;
};

/// The V4L2 capture devices present (/dev/video*), described.
std::vector<DeviceInfo> list_video_devices(V4l2Io& io);

}  // namespace kestrel::v4l2
