#include "ocams_stream.hpp"

#include <linux/videodev2.h>

#include <thread>

#include "raw_frame.hpp"

namespace kestrel::ocams {

std::string find_device(v4l2::V4l2Io& io, const std::string& name) {
  for (const auto& d : v4l2::list_video_devices(io))
    if (d.card.find(name) != std::string::npos) return d.path;
  return {};
}

OcamsStream::OcamsStream(v4l2::V4l2Io& io, StreamOptions options, std::function<Time()> now)
    : io_(io), options_(std::move(options)), now_(std::move(now)) {
  if (options_.device.empty()) {
    options_.device = find_device(io_, options_.name);
    if (options_.device.empty())
      throw Error("no " + options_.name + " found among /dev/video* (is it plugged in? `kestrel devices` lists them)");
  }
  try {
    open();
  } catch (const v4l2::DeviceLost& e) {
    throw Error("no " + options_.name + " found at " + options_.device + " (" + e.what() + ")");
  }
}

void OcamsStream::open() {
  auto camera = std::make_unique<v4l2::V4l2Camera>(io_, options_.device);
  info_ = camera->describe();
  camera->start(options_.format);
  // The oCamS's controls, by their standard ids (their names changed between kernels).
  struct Setting {
    const char* name;
    std::uint32_t id;
    std::optional<int> value;
  };
  const auto& c = options_.controls;
  std::optional<int> auto_exposure;
  if (c.auto_exposure) auto_exposure = *c.auto_exposure ? V4L2_EXPOSURE_APERTURE_PRIORITY : V4L2_EXPOSURE_MANUAL;
  // Auto exposure first: a manual exposure is only taken with it off.
  const Setting settings[] = {
      {"auto_exposure", V4L2_CID_EXPOSURE_AUTO, auto_exposure},
      {"exposure", V4L2_CID_EXPOSURE_ABSOLUTE, c.exposure},
      {"gain", static_cast<std::uint32_t>(camera->control_range(V4L2_CID_GAIN) ? V4L2_CID_GAIN : V4L2_CID_BRIGHTNESS),
       c.gain},
      {"white_balance_red", V4L2_CID_RED_BALANCE, c.white_balance_red},
      {"white_balance_blue", V4L2_CID_BLUE_BALANCE, c.white_balance_blue}};
  applied_.clear();
  for (const auto& s : settings) {
    if (!camera->control_range(s.id)) {
      if (s.value) throw Error(options_.device + " has no " + s.name + " control");
      continue;
    }
    if (s.value) camera->set_control(s.id, *s.value);
    applied_[s.name] = camera->control(s.id);
  }
  camera_ = std::move(camera);
  seen_ = {};
  clock_.reset();
  last_frame_ = std::chrono::steady_clock::now();
}

void OcamsStream::count_losses() {
  if (!camera_) return;
  const auto& k = camera_->counters();
  counters_.lost += (k.short_frames - seen_.short_frames) + (k.error_frames - seen_.error_frames) +
                    (k.sequence_gaps - seen_.sequence_gaps);
  seen_ = k;
}

void OcamsStream::lose(const std::string& why) {
  count_losses();
  camera_.reset();
  if (!options_.reconnect) throw Error(options_.device + ": " + why);
  last_try_ = std::chrono::steady_clock::now();
}

std::optional<RawCapture> OcamsStream::next(std::chrono::milliseconds wait) {
  const auto started = std::chrono::steady_clock::now();
  if (!camera_) {
    if (started - last_try_ < std::chrono::milliseconds(100)) {
      std::this_thread::sleep_for(std::min(wait, std::chrono::milliseconds(100)));
      return std::nullopt;
    }
    last_try_ = started;
    try {
      open();
      ++counters_.reconnects;
    } catch (const v4l2::DeviceLost&) {
      std::this_thread::sleep_for(std::min(wait, std::chrono::milliseconds(100)));
      return std::nullopt;  // not back yet
    }
  }
  std::optional<v4l2::CapturedFrame> frame;
  try {
    frame = camera_->next(wait);
  } catch (const v4l2::DeviceLost& e) {
    ++counters_.disconnects;
    lose(std::string("the camera went away (") + e.what() + ")");
    return std::nullopt;
  }
  count_losses();
  const auto now = std::chrono::steady_clock::now();
  if (!frame) {
    if (now - last_frame_ >= options_.stall_timeout) {
      ++counters_.stalls;
      lose("no frame for " + std::to_string(options_.stall_timeout.count()) + " ms: the stream stalled");
    }
    return std::nullopt;
  }
  last_frame_ = now;
  ++counters_.frames;
  RawCapture out;
  out.data = frame->data;
  out.device_ms = device_clock_ms(frame->data);
  out.stamp = clock_.map(out.device_ms, now_());
  return out;
}

}  // namespace kestrel::ocams
