// The `ocams_emulator` node: an oCamS made of another camera's frames, to rehearse the real
// camera's path without one. Each rectified pair (from sim_stereo, say) is sampled through the
// sensor's GRBG colour filter, packed into the words the camera sends with its clock in the first
// bytes, optionally written as a raw recording (ocams_replay reads it), and turned back into a
// StereoFrame by the driver's own FramePipeline.
#include <fmt/format.h>

#include <kestrel/plugin.hpp>
#include <opencv2/imgproc.hpp>

#include "frame_pipeline.hpp"
#include "kestrel/stereo_calibration/camera_info.hpp"
#include "raw_recording.hpp"

namespace kestrel::ocams {

struct OcamsEmulatorConfig {
  std::string raw_file;
  bool color = false;
  std::int64_t fps = 30;
};

namespace {

// The camera_info of a rectified camera: no distortion, R the identity, K the P's intrinsics.
calibration::CameraInfo rectified_info(const msg::StereoCalibration& c, bool right) {
  calibration::CameraInfo info;
  info.width = c.width;
  info.height = c.height;
  info.camera_name = right ? "ocams_emulator/right" : "ocams_emulator/left";
  info.k = {c.fx, 0, c.cx, 0, c.fy, c.cy, 0, 0, 1};
  info.d.assign(5, 0.0);
  info.r = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  info.p = {c.fx, 0, c.cx, right ? -c.fx * c.baseline_m : 0.0, 0, c.fy, c.cy, 0, 0, 0, 1, 0};
  return info;
}

cv::Mat as_bgr(const cv::Mat& image) {
  if (image.type() == CV_8UC3) return image;
  cv::Mat bgr;
  cv::cvtColor(image, bgr, cv::COLOR_GRAY2BGR);
  return bgr;
}

}  // namespace

class OcamsEmulatorNode final : public Node {
 public:
  static constexpr Input<msg::StereoFrame> kIn{"frame"};
  static constexpr Output<msg::StereoFrame> kFrame{"frame"};

  static NodeSpec spec() {
    using C = OcamsEmulatorConfig;
    ConfigSpec<C> c;
    c.param("raw_file", &C::raw_file)
        .describe("MCAP file the packed raw frames are written to, as ocams_stereo writes them; empty: none");
    c.param("color", &C::color).describe("publish BGR images instead of 8-bit grey");
    c.param("fps", &C::fps)
        .with_unit("Hz")
        .range(1, 240)
        .describe("the upstream camera's frame rate, written as the recording's format (ocams_replay ticks at it)");
    return NodeSpec("ocams_emulator", "Passes another camera's frames through the oCamS's raw format and driver")
        .details(
            "Mosaics each rectified pair to Bayer GRBG, packs it as the oCamS sends it (right byte, left byte, the "
            "clock in the first four bytes), records it when raw_file is set, and publishes what ocams_stereo's "
            "pipeline makes of it: the real camera's path, from rendered images.")
        .input(kIn, "rectified stereo frames")
        .output(kFrame, "the same frames through the oCamS's raw format and pipeline")
        .config(std::move(c));
  }

  explicit OcamsEmulatorNode(NodeInit& init) : cfg_(init.config<OcamsEmulatorConfig>()), id_(init.id()) {}

  void process(Context& ctx) override {
    const auto in = ctx.get(kIn);
    if (!pipeline_) start(*in);
    if (in->left.size() != cv::Size(format_.width, format_.height))
      throw Error(
          fmt::format("a {}x{} frame after {}x{} ones", in->left.cols, in->left.rows, format_.width, format_.height));
    const auto device_ms = static_cast<std::uint32_t>(in->stamp.count() / 1'000'000);
    const auto raw = pack(mosaic_grbg(as_bgr(in->left)), mosaic_grbg(as_bgr(in->right)), device_ms);
    if (raw_) raw_->write(raw, in->stamp, in->frame_index);
    msg::StereoFrame out = pipeline_->process(raw, in->stamp, in->frame_index);
    out.mount = in->mount;
    ctx.publish(kFrame, std::move(out));
    ++frames_;
  }

  void finish(Context& ctx) override {
    if (raw_) raw_->finish();
    ReportSection section;
    section.quantity("frames", frames_);
    if (raw_) raw_->report(section, cfg_.raw_file);
    ctx.set_report_section(ctx.id(), section);
  }

 private:
  void start(const msg::StereoFrame& first) {
    format_ = {first.left.cols, first.left.rows, 0};
    const auto left = rectified_info(first.calibration, false), right = rectified_info(first.calibration, true);
    pipeline_ = std::make_unique<FramePipeline>(PipelineOptions{format_.width, format_.height, cfg_.color},
                                                std::make_shared<calibration::StereoRectifier>(left, right));
    if (cfg_.raw_file.empty()) return;
    RawRecordingOptions r;
    r.topic = output_topic(id_, "raw");
    r.format = format_;
    r.format.fps = static_cast<int>(cfg_.fps);
    r.left_yaml = calibration::to_yaml(left);
    r.right_yaml = calibration::to_yaml(right);
    r.device = "ocams_emulator";
    raw_ = std::make_unique<RawRecorder>(cfg_.raw_file, r);
  }

  OcamsEmulatorConfig cfg_;
  std::string id_;
  RawFormat format_;
  std::unique_ptr<FramePipeline> pipeline_;
  std::unique_ptr<RawRecorder> raw_;
  std::uint64_t frames_ = 0;
};
KESTREL_REGISTER_NODE(OcamsEmulatorNode)

}  // namespace kestrel::ocams
