#pragma once
// The oCamS as a stream of raw frames stamped on the runtime's clock: the device found (by path,
// or by its name among /dev/video*), its format, rate and controls set, each frame's device clock
// mapped, and the failures of a real device lived through: a stream that stalls, a device
// unplugged mid-run and plugged back (reopened within 100 ms of its return when `reconnect`).
#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "device_clock.hpp"
#include "kestrel/v4l2/v4l2_camera.hpp"

namespace kestrel::ocams {

/// The camera's controls; unset ones keep the device's own values.
struct CameraControls {
  std::optional<int> exposure;  ///< V4L2 exposure (absolute), the device's units (100 us)
  std::optional<int> gain;
  std::optional<int> white_balance_red;
  std::optional<int> white_balance_blue;
  std::optional<bool> auto_exposure;
};

struct StreamOptions {
  std::string device;  ///< "/dev/video0", or empty: the first device whose name holds `name`
  std::string name = "oCamS";
  v4l2::CaptureFormat format;
  CameraControls controls;
  std::chrono::milliseconds stall_timeout{1000};
  bool reconnect = true;
};

struct StreamCounters {
  std::uint64_t frames = 0;
  std::uint64_t lost = 0;  ///< short, corrupt and skipped frames, and those the driver lost
  std::uint64_t stalls = 0;
  std::uint64_t disconnects = 0;
  std::uint64_t reconnects = 0;
};

/// One raw frame, valid until the next call to next().
struct RawCapture {
  std::span<const std::uint8_t> data;
  Time stamp{0};  ///< capture time on the runtime clock
  std::uint32_t device_ms = 0;
};

class OcamsStream {
 public:
  /// Opens and starts the camera. Throws Error with "no oCamS found" when there is none, or
  /// naming what the device refuses. `now` is the runtime clock.
  OcamsStream(v4l2::V4l2Io& io, StreamOptions options, std::function<Time()> now);

  /// The next frame, waiting at most `wait`; nullopt if none came (or the device is away and
  /// `reconnect` is on). Throws Error when the device stalls or vanishes without `reconnect`.
  std::optional<RawCapture> next(std::chrono::milliseconds wait);

  const StreamCounters& counters() const { return counters_; }
  /// What was set, as the device reports it, for the report: "exposure" -> 100, ...
  const std::map<std::string, int>& applied_controls() const { return applied_; }
  /// The device opened, with what it offers.
  const v4l2::DeviceInfo& device() const { return info_; }
  bool connected() const { return camera_ != nullptr; }

 private:
  void open();
  void lose(const std::string& why);
  void count_losses();

  v4l2::V4l2Io& io_;
  StreamOptions options_;
  std::function<Time()> now_;
  std::unique_ptr<v4l2::V4l2Camera> camera_;
  v4l2::DeviceInfo info_;
  DeviceClock clock_;
  StreamCounters counters_;
  v4l2::CaptureCounters seen_;  // the camera's counters already added to lost
  std::map<std::string, int> applied_;
  std::chrono::steady_clock::time_point last_frame_, last_try_;
};

/// The path of the first V4L2 device whose name holds `name`, or empty.
std::string find_device(v4l2::V4l2Io& io, const std::string& name);

}  // namespace kestrel::ocams
