// The `ocams_replay` node: raw frames that `ocams_stereo` recorded (its raw_file), fed through
// the very FramePipeline the camera's frames went through, at their recorded times. In lockstep a
// flight replays bit for bit, through any graph; under realtime at the recorded pace.
#include <fmt/format.h>

#include <kestrel/plugin.hpp>

#include "frame_pipeline.hpp"
#include "kestrel/camera_rig/camera_rig.hpp"
#include "kestrel/stereo_calibration/camera_info.hpp"
#include "raw_recording.hpp"

namespace kestrel::ocams {

struct OcamsReplayConfig {
  std::string file;
  std::string topic;
  std::string left_info;
  std::string right_info;
  bool color = false;
  std::string mount_frame = "hunter";
  Eigen::Vector3d mount_position_m{0.1, 0.0, 0.0};
  Eigen::Vector3d mount_rpy_deg{0.0, 0.0, 0.0};
};

class OcamsReplayNode final : public Node {
 public:
  static constexpr Output<msg::StereoFrame> kFrame{"frame"};

  static NodeSpec spec() {
    using C = OcamsReplayConfig;
    ConfigSpec<C> c;
    c.required("file", &C::file).describe("MCAP file of raw frames written by ocams_stereo's raw_file");
    c.param("topic", &C::topic).describe("the raw channel, /NODE/raw; empty: the file's one raw channel");
    c.param("left_info", &C::left_info)
        .describe("left camera_info YAML; empty: the calibration attached to the recording at capture");
    c.param("right_info", &C::right_info).describe("right camera_info YAML; empty: the one attached");
    c.param("color", &C::color).describe("publish BGR images instead of 8-bit grey");
    sensors::declare_camera_mount(c, &C::mount_frame, &C::mount_position_m, &C::mount_rpy_deg);
    return NodeSpec("ocams_replay", "Replays raw oCamS frames through the camera's own frame pipeline")
        .details(
            "Reads the raw frames an ocams_stereo node recorded, with the calibration attached to the file (or the "
            "files given), and unpacks, demosaics and rectifies them as the camera node did, publishing each at its "
            "recorded time. The run ends after the last frame.")
        .output(kFrame, "rectified stereo frames")
        .config(std::move(c));
  }

  explicit OcamsReplayNode(NodeInit& init)
      : cfg_(init.config<OcamsReplayConfig>()),
        reader_(cfg_.file, cfg_.topic),
        mount_(sensors::mount_on_vehicle(cfg_.mount_frame, cfg_.mount_position_m, cfg_.mount_rpy_deg)) {
    const auto info = [&](const std::string& path, const std::optional<std::string>& attached, const char* side) {
      if (!path.empty()) return calibration::load_camera_info(path);
      if (!attached) throw Error(fmt::format("{} has no {}.yaml attached: give {}_info", cfg_.file, side, side));
      return calibration::parse_camera_info(*attached, cfg_.file + " (" + side + ".yaml)");
    };
    auto rectifier = std::make_shared<calibration::StereoRectifier>(
        info(cfg_.left_info, reader_.left_yaml(), "left"), info(cfg_.right_info, reader_.right_yaml(), "right"));
    pipeline_ = std::make_unique<FramePipeline>(
        PipelineOptions{reader_.format().width, reader_.format().height, cfg_.color}, rectifier);
    init.set_rate(static_cast<double>(reader_.format().fps));
  }

  void tick(Context& ctx) override {
    const auto now = static_cast<mcap::Timestamp>(std::max<std::int64_t>(0, ctx.now().count()));
    reader_.read(next_, now + 1, [&](const RawRecord& r) {
      msg::StereoFrame frame = pipeline_->process(r.raw, r.stamp, r.frame_index);
      frame.mount = mount_;
      ctx.publish(kFrame, std::move(frame));
      ++published_;
    });
    next_ = now + 1;
    if (next_ > reader_.end_time()) ctx.end_of_stream();
  }

  void finish(Context& ctx) override {
    ctx.set_report_section(ctx.id(), ReportSection()
                                         .info("file", cfg_.file)
                                         .info("topic", reader_.topic())
                                         .info("format", fmt::format("{}x{}@{}", reader_.format().width,
                                                                     reader_.format().height, reader_.format().fps))
                                         .quantity("recorded", reader_.frame_count(), "frames")
                                         .quantity("published", published_, "frames")
                                         .info("problems", reader_.problems())
                                         .markdown(fmt::format("Replayed {} of {} raw frames from `{}`.\n", published_,
                                                               reader_.frame_count(), cfg_.file)));
  }

 private:
  OcamsReplayConfig cfg_;
  RawReader reader_;
  msg::CameraMount mount_;
  std::unique_ptr<FramePipeline> pipeline_;
  mcap::Timestamp next_ = 0;
  std::uint64_t published_ = 0;
};
KESTREL_REGISTER_NODE(OcamsReplayNode)

}  // namespace kestrel::ocams
