// The `stereo_images` node: recorded stereo from any camera as kestrel StereoFrames. Pairs come
// from two folders, two numbered patterns, two image files or a side-by-side video; the calibration from a ROS
// camera_info pair or an OpenCV stereo calibration file. Raw images are rectified with it (the
// same StereoRectifier the oCamS driver uses), rectified ones pass through. So a public dataset
// or another stereo camera drives every graph (docs/hardware.md).
#include <fmt/format.h>

#include <kestrel/plugin.hpp>
#include <opencv2/imgproc.hpp>

#include "kestrel/camera_rig/camera_rig.hpp"
#include "kestrel/stereo_calibration/camera_info.hpp"
#include "kestrel/stereo_calibration/middlebury_calibration.hpp"
#include "kestrel/stereo_calibration/stereo_rectifier.hpp"
#include "kestrel/stereo_images/pair_source.hpp"

namespace kestrel::stereo_images {

struct StereoImagesConfig {
  std::string left;
  std::string right;
  std::string video;
  std::int64_t start_index = 0;
  std::string left_info;
  std::string right_info;
  std::string opencv_calibration;
  std::string middlebury_calibration;
  enum class Images { raw, rectified };
  Images images = Images::raw;
  double fps = 30.0;
  bool color = false;
  std::string mount_frame = "world";
  Eigen::Vector3d mount_position_m{0.0, 0.0, 0.0};
  Eigen::Vector3d mount_rpy_deg{0.0, 0.0, 0.0};
};

namespace {

// The one calibration given (the spec's rules hold: exactly one, and each whole).
std::pair<calibration::CameraInfo, calibration::CameraInfo> calibration_of(const StereoImagesConfig& c) {
  if (!c.middlebury_calibration.empty())
    return calibration::load_middlebury_calibration(c.middlebury_calibration).camera_infos();
  if (!c.opencv_calibration.empty())
    return calibration::camera_infos(calibration::load_opencv_stereo(c.opencv_calibration));
  return {calibration::load_camera_info(c.left_info), calibration::load_camera_info(c.right_info)};
}

// Images rectified already: only their rectified camera (the projections P) is used.
calibration::CameraInfo as_rectified(calibration::CameraInfo c) {
  c.d.assign(c.d.size(), 0.0);
  c.r = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  c.k = {c.p[0], c.p[1], c.p[2], c.p[4], c.p[5], c.p[6], 0, 0, 1};
  return c;
}

cv::Mat as_wanted(const cv::Mat& m, bool color) {
  if (color && m.channels() == 1) {
    cv::Mat out;
    cv::cvtColor(m, out, cv::COLOR_GRAY2BGR);
    return out;
  }
  if (!color && m.channels() == 3) {
    cv::Mat out;
    cv::cvtColor(m, out, cv::COLOR_BGR2GRAY);
    return out;
  }
  return m;
}

}  // namespace

class StereoImagesNode final : public Node {
 public:
  static constexpr Output<msg::StereoFrame> kFrame{"frame"};

  static NodeSpec spec() {
    using C = StereoImagesConfig;
    ConfigSpec<C> c;
    c.param("left", &C::left)
        .describe("folder of left images (in name order), a pattern (left/%06d.png), or one image file");
    c.param("right", &C::right).describe("folder, pattern or file of the right images, as many as the left");
    c.param("video", &C::video).describe("a side-by-side video instead: left half, right half");
    c.param("start_index", &C::start_index).at_least(0).describe("patterns: the first image's number");
    c.param("left_info", &C::left_info).describe("ROS camera_info YAML of the left camera");
    c.param("right_info", &C::right_info).describe("ROS camera_info YAML of the right camera");
    c.param("opencv_calibration", &C::opencv_calibration)
        .describe("or an OpenCV stereo calibration (K1, D1, K2, D2, R, T, image_width, image_height), rectified here");
    c.param("middlebury_calibration", &C::middlebury_calibration)
        .describe(
            "or a Middlebury calib.txt (cam0, cam1, doffs, baseline in mm): the right image is moved by doffs onto "
            "the left camera's principal point, so that disparity gives depth");
    c.choice("images", &C::images, {{"raw", C::Images::raw}, {"rectified", C::Images::rectified}})
        .describe("raw: rectified here with the calibration; rectified: already, only P's camera is used");
    c.param("fps", &C::fps).with_unit("Hz").range(0.1, 1000.0).describe("frames a second: the pairs' times");
    c.param("color", &C::color).describe("publish BGR images instead of 8-bit grey");
    sensors::declare_camera_mount(c, &C::mount_frame, &C::mount_position_m, &C::mount_rpy_deg);
    c.requirement("exactly one calibration: left_info and right_info, opencv_calibration or middlebury_calibration",
                  {"left_info", "right_info", "opencv_calibration", "middlebury_calibration"}, [](const C& k) {
                    return !k.opencv_calibration.empty() + !k.middlebury_calibration.empty() +
                               (!k.left_info.empty() || !k.right_info.empty()) ==
                           1;
                  });
    c.rule("left_info and right_info together", {"left_info", "right_info"},
           [](const C& k) { return k.left_info.empty() == k.right_info.empty(); });
    c.rule("middlebury_calibration with images: raw (it moves the right image by doffs, so that disparity gives depth)",
           {"middlebury_calibration", "images"},
           [](const C& k) { return k.middlebury_calibration.empty() || k.images == C::Images::raw; });
    c.requirement("left and right, or video", {"left", "right", "video"}, [](const C& k) {
      return k.video.empty() ? !k.left.empty() && !k.right.empty() : k.left.empty() && k.right.empty();
    });
    return NodeSpec("stereo_images", "Stereo pairs from image folders, numbered files or a side-by-side video")
        .details(
            "Publishes one pair every 1/fps s, from time 0, as rectified StereoFrames: raw pairs are rectified with "
            "the "
            "calibration (a ROS camera_info pair or an OpenCV stereo calibration) by the oCamS driver's rectifier. "
            "The run ends after the last pair.")
        .output(kFrame, "rectified stereo frames")
        .config(std::move(c));
  }

  explicit StereoImagesNode(NodeInit& init)
      : cfg_(init.config<StereoImagesConfig>()),
        source_(PairSourceOptions{cfg_.left, cfg_.right, cfg_.video, static_cast<int>(cfg_.start_index)}),
        mount_(sensors::mount_on_vehicle(cfg_.mount_frame, cfg_.mount_position_m, cfg_.mount_rpy_deg)) {
    auto [left, right] = calibration_of(cfg_);
    if (cfg_.images == StereoImagesConfig::Images::rectified) {
      left = as_rectified(left);
      right = as_rectified(right);
    }
    rectifier_ = std::make_unique<calibration::StereoRectifier>(left, right);
    init.set_rate(cfg_.fps);
  }

  void tick(Context& ctx) override {
    auto pair = source_.next();
    if (!pair) {
      ctx.end_of_stream();
      return;
    }
    msg::StereoFrame frame;
    frame.stamp = ctx.now();
    frame.frame_index = published_++;
    rectifier_->rectify(as_wanted(pair->first, cfg_.color), as_wanted(pair->second, cfg_.color), frame.left,
                        frame.right);
    frame.calibration = rectifier_->calibration();
    frame.mount = mount_;
    ctx.publish(kFrame, std::move(frame));
  }

  void finish(Context& ctx) override {
    ctx.set_report_section(ctx.id(), ReportSection()
                                         .info("source", source_.kind())
                                         .quantity("pairs", source_.size())
                                         .quantity("published", published_)
                                         .info("rectified_here", !rectifier_->passthrough())
                                         .markdown(fmt::format("Published {} of {} stereo pairs ({}).\n", published_,
                                                               source_.size(), source_.kind())));
  }

 private:
  StereoImagesConfig cfg_;
  PairSource source_;
  msg::CameraMount mount_;
  std::unique_ptr<calibration::StereoRectifier> rectifier_;
  std::uint64_t published_ = 0;
};
KESTREL_REGISTER_NODE(StereoImagesNode)

}  // namespace kestrel::stereo_images
