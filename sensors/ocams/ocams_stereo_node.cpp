// The `ocams_stereo` node: the WithRobot oCamS-1CGN-U as a stereo camera. Frames come through
// V4L2 (OcamsStream), become rectified StereoFrames through the same FramePipeline raw replay
// uses, and carry the camera's mount. It publishes what sim_stereo publishes, so a graph swaps
// one for the other by changing the node's type and its parameters (docs/hardware.md).
#include <fmt/format.h>

#include <fstream>
#include <kestrel/plugin.hpp>
#include <sstream>

#include "frame_pipeline.hpp"
#include "kestrel/camera_rig/camera_rig.hpp"
#include "kestrel/stereo_calibration/camera_info.hpp"
#include "kestrel/v4l2/ocams_modes.hpp"
#include "ocams_stream.hpp"
#include "raw_recording.hpp"

namespace kestrel::ocams {

struct OcamsStereoConfig {
  std::string device;
  std::int64_t width = 640;
  std::int64_t height = 480;
  std::int64_t fps = 30;
  bool color = false;
  std::string left_info;
  std::string right_info;
  std::int64_t exposure = -1;
  std::int64_t gain = -1;
  std::int64_t white_balance_red = -1;
  std::int64_t white_balance_blue = -1;
  enum class AutoExposure { device, on, off };
  AutoExposure auto_exposure = AutoExposure::device;
  double stall_timeout_s = 1.0;
  bool reconnect = true;
  std::string raw_file;
  std::int64_t raw_queue_frames = 90;
  std::string mount_frame = "hunter";
  Eigen::Vector3d mount_position_m{0.1, 0.0, 0.0};
  Eigen::Vector3d mount_rpy_deg{0.0, 0.0, 0.0};
};

namespace {

std::string read_text(const std::string& path, const char* what) {
  std::ifstream in(path);
  if (!in)
    throw Error(std::string("cannot read the ") + what + " camera_info file '" + path +
                "' (docs/hardware.md: calibrating the camera)");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::optional<int> unless_negative(std::int64_t v) {
  return v < 0 ? std::nullopt : std::optional<int>(static_cast<int>(v));
}

}  // namespace

class OcamsStereoNode final : public Node {
 public:
  static constexpr Output<msg::StereoFrame> kFrame{"frame"};

  static NodeSpec spec() {
    using C = OcamsStereoConfig;
    ConfigSpec<C> c;
    c.param("device", &C::device).describe("V4L2 device, /dev/video0 or a udev name; empty: the first oCamS found");
    c.param("width", &C::width).with_unit("px").describe("per-eye width: 1280, 640 or 320");
    c.param("height", &C::height).with_unit("px").describe("per-eye height: 960, 720, 480, 360 or 240");
    c.param("fps", &C::fps).with_unit("Hz").describe("frame rate the camera streams at");
    c.rule("width x height @ fps is a format the camera streams (" + ocams_modes_text() + ")",
           {"width", "height", "fps"}, [](const C& k) {
             return ocams_streams(static_cast<int>(k.width), static_cast<int>(k.height), static_cast<int>(k.fps));
           });
    c.param("color", &C::color).describe("publish BGR images instead of 8-bit grey");
    c.required("left_info", &C::left_info).describe("ROS camera_info YAML of the left camera, at the streamed size");
    c.required("right_info", &C::right_info)
        .describe("ROS camera_info YAML of the right camera; its P gives the baseline");
    c.param("exposure", &C::exposure)
        .range(-1, 100000)
        .describe("exposure in the device's units (100 us); -1: the device's");
    c.param("gain", &C::gain).range(-1, 100000).describe("analogue gain; -1: the device's");
    c.param("white_balance_red", &C::white_balance_red).range(-1, 100000).describe("red gain; -1: the device's");
    c.param("white_balance_blue", &C::white_balance_blue).range(-1, 100000).describe("blue gain; -1: the device's");
    c.choice("auto_exposure", &C::auto_exposure,
             {{"device", C::AutoExposure::device}, {"on", C::AutoExposure::on}, {"off", C::AutoExposure::off}})
        .describe("on, off, or as the device has it; a manual exposure needs off");
    c.param("stall_timeout_s", &C::stall_timeout_s)
        .with_unit("s")
        .range(0.05, 60.0)
        .describe("a stream with no frame this long has stalled: reopened with reconnect, an error without");
    c.param("reconnect", &C::reconnect)
        .describe("reopen the camera when it stalls or is unplugged, as soon as it is back; false: stop the run");
    c.param("raw_file", &C::raw_file)
        .describe("MCAP file the raw frames are written to, as they came off USB, for ocams_replay; empty: none");
    c.param("raw_queue_frames", &C::raw_queue_frames)
        .range(1, 10000)
        .describe("raw frames waiting for the writer thread before new ones are dropped (and counted)");
    sensors::declare_camera_mount(c, &C::mount_frame, &C::mount_position_m, &C::mount_rpy_deg);
    return NodeSpec("ocams_stereo", "WithRobot oCamS-1CGN-U stereo camera (V4L2), rectified from camera_info files")
        .details(
            "Streams the camera's Bayer GRBG pairs, splits, demosaics and rectifies them and publishes the same "
            "StereoFrame as sim_stereo, stamped with the camera's clock mapped onto the run's. A missing camera stops "
            "the run at start with 'no oCamS found'; a stalled or unplugged one is "
            "reopened when it returns (reconnect). The report counts frames, lost frames and reconnects.")
        .needs_executor(ExecutorNeed::realtime, "it reads a real camera (ocams_replay replays one in lockstep)")
        .output(kFrame, "rectified stereo frames")
        .config(std::move(c));
  }

  explicit OcamsStereoNode(NodeInit& init) : OcamsStereoNode(init, init.config<OcamsStereoConfig>()) {}

  void tick(Context& ctx) override {
    ctx_ = &ctx;
    const auto capture = stream_->next(wait_);
    if (!capture) return;
    const std::uint64_t index = frames_++;
    if (raw_) raw_->write(capture->data, capture->stamp, index);
    msg::StereoFrame frame = pipeline_->process(capture->data, capture->stamp, index);
    frame.mount = mount_;
    ctx.publish(kFrame, std::move(frame));
  }

  void finish(Context& ctx) override {
    if (raw_) raw_->finish();
    const StreamCounters& k = stream_->counters();
    nlohmann::json controls = nlohmann::json::object();
    for (const auto& [name, value] : stream_->applied_controls()) controls[name] = value;
    ReportSection section;
    section.info("device", device_path_)
        .info("card", stream_->device().card)
        .info("format", fmt::format("{}x{}@{}", cfg_.width, cfg_.height, cfg_.fps))
        .quantity("controls", controls)
        .quantity("frames", k.frames)
        .metric("lost", k.lost, "frames", Better::lower)
        .metric("stalls", k.stalls, "", Better::lower)
        .metric("disconnects", k.disconnects, "", Better::lower)
        .quantity("reconnects", k.reconnects)
        .markdown(fmt::format("{} frames from {} ({}), {} lost, {} reconnect(s).\n", k.frames, device_path_,
                              stream_->device().card, k.lost, k.reconnects));
    if (raw_) raw_->report(section, cfg_.raw_file);
    ctx.set_report_section(ctx.id(), section);
  }

 private:
  OcamsStereoNode(NodeInit& init, const OcamsStereoConfig& cfg)
      : cfg_(cfg),
        wait_(std::chrono::milliseconds(static_cast<int>(1500 / cfg.fps))),
        mount_(sensors::mount_on_vehicle(cfg.mount_frame, cfg.mount_position_m, cfg.mount_rpy_deg)) {
    StreamOptions o;
    o.device = cfg.device;
    o.format = {static_cast<int>(cfg.width), static_cast<int>(cfg.height), static_cast<int>(cfg.fps)};
    o.controls = {unless_negative(cfg.exposure), unless_negative(cfg.gain), unless_negative(cfg.white_balance_red),
                  unless_negative(cfg.white_balance_blue),
                  cfg.auto_exposure == OcamsStereoConfig::AutoExposure::device
                      ? std::nullopt
                      : std::optional<bool>(cfg.auto_exposure == OcamsStereoConfig::AutoExposure::on)};
    o.stall_timeout = std::chrono::milliseconds(static_cast<int>(cfg.stall_timeout_s * 1000));
    o.reconnect = cfg.reconnect;
    // The camera first: without one, that is what the user must hear, not a calibration problem.
    stream_ = std::make_unique<OcamsStream>(v4l2::system_v4l2_io(), o, [this] { return ctx_ ? ctx_->now() : Time(0); });
    device_path_ = o.device.empty() ? find_device(v4l2::system_v4l2_io(), o.name) : o.device;
    const std::string left = read_text(cfg.left_info, "left"), right = read_text(cfg.right_info, "right");
    auto rectifier = std::make_shared<calibration::StereoRectifier>(
        calibration::parse_camera_info(left, cfg.left_info), calibration::parse_camera_info(right, cfg.right_info));
    pipeline_ = std::make_unique<FramePipeline>(
        PipelineOptions{static_cast<int>(cfg.width), static_cast<int>(cfg.height), cfg.color}, rectifier);
    if (!cfg.raw_file.empty()) {
      RawRecordingOptions r;
      r.topic = output_topic(init.id(), "raw");
      r.format = {static_cast<int>(cfg.width), static_cast<int>(cfg.height), static_cast<int>(cfg.fps)};
      r.left_yaml = left;
      r.right_yaml = right;
      r.device = stream_->device().card + " at " + device_path_;
      r.queue_frames = static_cast<std::size_t>(cfg.raw_queue_frames);
      raw_ = std::make_unique<RawRecorder>(cfg.raw_file, r);
    }
    init.set_rate(static_cast<double>(cfg.fps));
  }

  OcamsStereoConfig cfg_;
  std::chrono::milliseconds wait_;
  msg::CameraMount mount_;
  std::unique_ptr<OcamsStream> stream_;
  std::string device_path_;
  std::unique_ptr<FramePipeline> pipeline_;
  std::unique_ptr<RawRecorder> raw_;
  Context* ctx_ = nullptr;
  std::uint64_t frames_ = 0;
};
KESTREL_REGISTER_NODE(OcamsStereoNode)

}  // namespace kestrel::ocams
