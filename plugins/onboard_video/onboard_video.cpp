// The `onboard_video` node: a video of what the hunter saw, the left image with the detections,
// the tracks, the selected target and the aim point drawn on it (overlay.hpp), frame by frame,
// into the run report (Motion-JPEG AVI, OpenCV VideoWriter). The frame, the detections and the
// tracks of one capture are matched by their stamp.
#include <fmt/format.h>
#include <unistd.h>

#include <deque>
#include <filesystem>
#include <fstream>
#include <kestrel/plugin.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>
#include <sstream>

#include "overlay.hpp"

namespace kestrel::video {

struct OnboardVideoConfig {
  std::string name = "onboard";
  double fps = 30.0;
  std::int64_t max_frames = 3600;
  double scale = 0.5;
  Eigen::Vector3d aim_point_m{0.0, 1.0, 2.0};
  double capture_radius_m = 0.5;
};

class OnboardVideoNode final : public Node {
 public:
  static constexpr Input<msg::StereoFrame> kFrame{"frame"};
  static constexpr Input<msg::Detections> kDetections{"detections"};
  static constexpr Input<msg::Tracks> kTracks{"tracks"};

  static NodeSpec spec() {
    using C = OnboardVideoConfig;
    ConfigSpec<C> c;
    c.param("name", &C::name).describe("file name, without .avi");
    c.param("fps", &C::fps).with_unit("Hz").range(1.0, 240.0).describe("frame rate written in the file");
    c.param("max_frames", &C::max_frames).range(1, 1000000).describe("frames written at most (later ones counted)");
    c.param("scale", &C::scale)
        .range(0.1, 1.0)
        .describe("video size against the camera image (file size against detail)");
    c.param("aim_point_m", &C::aim_point_m).with_unit("m").range(-50.0, 50.0).describe("x_E^d, drawn as a cross");
    c.param("capture_radius_m", &C::capture_radius_m)
        .with_unit("m")
        .range(0.0, 10.0)
        .describe("drawn as a circle around the aim point, at its depth");
    return NodeSpec("onboard_video", "Video of the left image with detections, tracks, target and aim point")
        .details(
            "Writes NAME.avi (Motion-JPEG) into the report folder: one frame per tracks message, drawn on the "
            "camera frame and detections of the same capture time. Does nothing without a report folder.")
        .input(kFrame, "the camera's frames", {.trigger = Trigger::latest})
        .input(kDetections, "detections of those frames", {.trigger = Trigger::latest, .optional = true})
        .input(kTracks, "the tracker's tracks, one video frame each")
        .config(std::move(c));
  }

  explicit OnboardVideoNode(NodeInit& init) : cfg_(init.config<OnboardVideoConfig>()) {}

  void process(Context& ctx) override {
    if (!ctx.keeps_artifacts()) return;
    const auto tracks = ctx.get(kTracks);
    const auto frame = ctx.get(kFrame);
    if (!frame || frame->stamp != tracks->stamp || frame->left.empty()) {
      ++unmatched_;  // the frame of this capture is not the newest one: nothing to draw on
      return;
    }
    if (written_ >= static_cast<std::uint64_t>(cfg_.max_frames)) {
      ++beyond_;
      return;
    }
    const auto detections = ctx.get(kDetections);
    const msg::Detections* same = detections && detections->stamp == tracks->stamp ? detections.get() : nullptr;
    const cv::Mat image = draw_overlay(*frame, same, tracks.get(), {cfg_.aim_point_m, cfg_.capture_radius_m});
    cv::Mat video;
    cv::resize(image, video, cv::Size(), cfg_.scale, cfg_.scale, cv::INTER_AREA);
    if (!writer_.isOpened()) {
      file_ = std::filesystem::temp_directory_path() /
              fmt::format("kestrel-video-{}-{}-{}.avi", ::getpid(), ctx.id(), reinterpret_cast<std::uintptr_t>(this));
      if (!writer_.open(file_.string(), cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), cfg_.fps, video.size()))
        throw Error("cannot open a Motion-JPEG video writer (OpenCV videoio) at " + file_.string());
    }
    writer_.write(video);
    ++written_;
    // The frame with a target nearest the aim point so far, for report.md, which shows no video.
    if (same_target_distance(*tracks) < best_distance_) {
      best_distance_ = same_target_distance(*tracks);
      best_ = image.clone();
      best_at_ = to_seconds(tracks->stamp);
    }
  }

  void finish(Context& ctx) override {
    const std::string id = ctx.id();
    ctx.set_report_section(
        id, ReportSection()
                .quantity("frames", written_)
                .quantity("unmatched", unmatched_)
                .quantity("beyond_max_frames", beyond_)
                .markdown(fmt::format("{} frames in {}.avi; {} tracks without their frame, {} beyond max_frames.\n",
                                      written_, cfg_.name, unmatched_, beyond_)));
    if (!writer_.isOpened()) return;
    writer_.release();
    std::ifstream in(file_, std::ios::binary);
    std::stringstream bytes;
    bytes << in.rdbuf();
    std::filesystem::remove(file_);
    if (!best_.empty()) {
      std::vector<unsigned char> png;
      cv::imencode(".png", best_, png);
      ctx.add_artifact(cfg_.name + ".png", std::string_view(reinterpret_cast<const char*>(png.data()), png.size()),
                       fmt::format("onboard view at {:.2f} s, the target closest to the aim point (a frame of {}.avi)",
                                   best_at_, cfg_.name));
    }
    ctx.add_artifact(cfg_.name + ".avi", bytes.str(),
                     "the left image with detections (orange boxes), tracks (blue), the target (red) and the aim "
                     "point with the net's radius (green)");
  }

  ~OnboardVideoNode() override {
    if (writer_.isOpened()) writer_.release();
    std::error_code ignored;
    if (!file_.empty()) std::filesystem::remove(file_, ignored);
  }

 private:
  double same_target_distance(const msg::Tracks& tracks) const {
    const msg::Track* t = tracks.selected();
    return t ? (t->position() - cfg_.aim_point_m).norm() : std::numeric_limits<double>::infinity();
  }

  OnboardVideoConfig cfg_;
  cv::VideoWriter writer_;
  cv::Mat best_;
  double best_distance_ = std::numeric_limits<double>::infinity(), best_at_ = 0.0;
  std::filesystem::path file_;
  std::uint64_t written_ = 0, unmatched_ = 0, beyond_ = 0;
};
KESTREL_REGISTER_NODE(OnboardVideoNode)

}  // namespace kestrel::video
