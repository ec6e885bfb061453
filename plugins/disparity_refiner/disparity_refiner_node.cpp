// The `disparity_refiner` node: places each detection from its object's disparity measured as a
// whole, at full resolution and to a fraction of a pixel (object_disparity.hpp), at the image
// centroid of its pixels. Between the clusterer and whatever consumes its detections; it needs
// the stereo pair and stereo_depth's cloud of the same capture (at full or reduced resolution:
// matched at half resolution, the objects are found coarse and measured fine).
#include <deque>
#include <kestrel/messages/detections.hpp>
#include <kestrel/messages/point_cloud.hpp>
#include <kestrel/messages/stereo_frame.hpp>
#include <kestrel/plugin.hpp>
#include <opencv2/imgproc.hpp>

#include "object_disparity.hpp"

namespace kestrel::refine {

struct RefinerConfig {
  enum class Method { none, mean, match };
  Method refine = Method::match;
  double margin_m = 0.05;
  std::int64_t erode_px = 0;
  std::int64_t min_pixels = 20;
  double search_px = 2.0;
  std::int64_t iterations = 10;
  std::int64_t history = 8;
  BackgroundOptions background;
  double centre_behind_surface_m = 0.0;
};

class DisparityRefiner final : public Node {
 public:
  static constexpr Input<msg::Detections> kDetections{"detections"};
  static constexpr Input<msg::StereoFrame> kFrame{"frame"};
  static constexpr Input<msg::PointCloud> kCloud{"cloud"};
  static constexpr Output<msg::Detections> kOut{"detections"};

  static NodeSpec spec() {
    using C = RefinerConfig;
    ConfigSpec<C> c;
    c.choice("refine", &C::refine, {{"none", C::Method::none}, {"mean", C::Method::mean}, {"match", C::Method::match}})
        .describe(
            "none: the clusterer's centroid (for ablation); mean: the robust mean of the object's SGBM disparities; "
            "match: the object's pixels matched as a whole against the right image, to a fraction of a pixel");
    c.param("margin_m", &C::margin_m)
        .with_unit("m")
        .range(0.0, 10.0)
        .describe("the object's pixels: full-resolution points within the detection's box grown by this");
    c.param("erode_px", &C::erode_px)
        .range(0, 20)
        .with_unit("px")
        .describe(
            "pixels peeled off the object's silhouette, which bleed onto the background; 0 keeps them: against a "
            "plain sky the silhouette's edge is the texture that places the object best");
    c.param("min_pixels", &C::min_pixels).range(1, 1000000).describe("fewer object pixels: left as it is");
    c.param("search_px", &C::search_px)
        .with_unit("px")
        .range(0.5, 64.0)
        .describe("match: whole-pixel search around the SGBM disparity, each way");
    c.param("iterations", &C::iterations).range(0, 100).describe("match: Gauss-Newton steps after the search");
    c.param("background_ratio", &C::background, &BackgroundOptions::ratio)
        .range(0.0, 1.0)
        .describe(
            "match: a pixel of the object's mask is background when a disparity behind the object explains it at "
            "this share of the object's own cost or less (the matcher's blocks spread objects onto the background "
            "around them); 0: keep every pixel");
    c.param("background_radius_px", &C::background, &BackgroundOptions::radius_px)
        .range(0, 5)
        .with_unit("px")
        .describe("match: the background test compares windows of 2 r + 1 pixels square");
    c.param("background_gap_px", &C::background, &BackgroundOptions::gap_px)
        .range(0.5, 20.0)
        .with_unit("px")
        .describe("match: the background's disparities tried: 0 up to the object's minus this");
    c.param("centre_behind_surface_m", &C::centre_behind_surface_m)
        .range(0.0, 10.0)
        .with_unit("m")
        .describe(
            "the target model: how far its centre lies behind the surface the camera measures, along the line of "
            "sight (the simulated hexacopter: 0.077 m, from its rendered depth by kestrel_detection_bias); 0: "
            "detections on the surface");
    c.param("history", &C::history)
        .range(1, 1000)
        .describe("frames and clouds kept to find the capture of a late detection");
    return NodeSpec("disparity_refiner", "Places detections from their object's sub-pixel disparity")
        .details(
            "For each detection, the stereo cloud's points inside its box (grown by margin_m) are projected back "
            "into the left image (each as the square of pixels it was matched from): the object's pixels, holes "
            "closed and the silhouette eroded by erode_px. With refine: match, pixels that a disparity behind the "
            "object explains clearly better than its own are taken out (background_ratio). Its disparity is "
            "measured as a whole (refine: match, or mean), and the detection is placed at that disparity under the "
            "pixels' image centroid (averaging in disparity, not depth), then centre_behind_surface_m further along "
            "the line of sight. A detection without enough pixels, texture or a match, or whose capture is no "
            "longer held, passes unchanged and is counted.")
        .input(kDetections, "the clusterer's detections")
        .input(kFrame, "the stereo pairs they are found in (kept by capture time)")
        .input(kCloud, "the clouds of those pairs (stereo_depth, before the voxel grid), at any downscale")
        .output(kOut, "the same detections, placed from their refined disparity")
        .config(std::move(c));
  }

  explicit DisparityRefiner(NodeInit& init) : cfg_(init.config<RefinerConfig>()) {}

  void process(Context& ctx) override {
    if (ctx.triggered_by(kFrame)) return keep(ctx.get(kFrame));
    if (ctx.triggered_by(kCloud)) return keep(ctx.get(kCloud));
    const auto in = ctx.get(kDetections);
    msg::Detections out = *in;
    if (cfg_.refine != RefinerConfig::Method::none) {
      Capture* capture = find(in->stamp);
      for (auto& d : out.items) {
        ++detections_;
        if (!capture) {
          ++no_capture_;
          continue;
        }
        if (const auto p = refine(*capture, d)) {
          d.position = *p;
          ++refined_;
        }
      }
    }
    ctx.publish(kOut, std::move(out));
  }

  void finish(Context& ctx) override {
    const std::string id = ctx.id();
    const double shift = refined_ ? shift_sum_ / static_cast<double>(refined_) : 0.0;
    ctx.set_report_section(
        id, ReportSection()
                .quantity("detections", detections_)
                .quantity("refined", refined_)
                .quantity("no_capture", no_capture_)
                .quantity("no_pixels", no_pixels_)
                .quantity("no_match", no_match_)
                .quantity("background_pixels_dropped", background_pixels_)
                .quantity("mean_abs_shift_px", refined_ ? nlohmann::json(shift) : nlohmann::json(), "px")
                .markdown(fmt::format("{} of {} detections placed from their object's disparity; left as they were: "
                                      "{} without their capture, {} with too few pixels, {} without a match. Mean "
                                      "|refined - SGBM median| disparity {:.3f} px; {} background pixels taken out "
                                      "of the objects' masks.\n",
                                      refined_, detections_, no_capture_, no_pixels_, no_match_, shift,
                                      background_pixels_)));
  }

 private:
  // One capture's frame and cloud, shared with the nodes that made them (never copied); the
  // grey float images the match needs are made the first time a detection asks for them.
  struct Capture {
    Time stamp;
    std::shared_ptr<const msg::StereoFrame> frame;
    std::shared_ptr<const msg::PointCloud> cloud;
    cv::Mat left, right;
  };

  // Frames and clouds by capture time: the detections of a capture arrive after its frame and
  // cloud, and perhaps after the next frame's (realtime executor).
  void keep(std::shared_ptr<const msg::StereoFrame> frame) { slot(frame->stamp)->frame = std::move(frame); }
  void keep(std::shared_ptr<const msg::PointCloud> cloud) {
    if (!cloud->points) throw Error("point cloud message without points");
    if (cloud->pixels_per_point < 1)
      throw Error(
          "the cloud's points are not image samples (pixels_per_point 0): connect stereo_depth's cloud, "
          "before the voxel grid");
    slot(cloud->stamp)->cloud = std::move(cloud);
  }

  Capture* slot(Time stamp) {
    for (auto& c : captures_)
      if (c.stamp == stamp) return &c;
    captures_.push_back(Capture{});
    captures_.back().stamp = stamp;
    while (static_cast<std::int64_t>(captures_.size()) > cfg_.history) captures_.pop_front();
    return &captures_.back();
  }

  Capture* find(Time stamp) {
    for (auto& c : captures_)
      if (c.stamp == stamp && c.frame && c.cloud) return &c;
    return nullptr;
  }

  static cv::Mat grey(const cv::Mat& image) {
    cv::Mat g, f;
    if (image.channels() == 3)
      cv::cvtColor(image, g, cv::COLOR_BGR2GRAY);
    else
      g = image;
    g.convertTo(f, CV_32F);
    return f;
  }

  std::optional<Eigen::Vector3d> refine(Capture& c, const msg::Detection& d) {
    const msg::StereoCalibration& calibration = c.frame->calibration;
    auto mask =
        object_mask(*c.cloud->points, calibration, d.position, 0.5 * d.extent, cfg_.margin_m,
                    static_cast<int>(cfg_.erode_px), static_cast<int>(cfg_.min_pixels), c.cloud->pixels_per_point);
    if (!mask) {
      ++no_pixels_;
      return std::nullopt;
    }
    if (cfg_.refine == RefinerConfig::Method::match && c.left.empty()) {
      c.left = grey(c.frame->left);
      c.right = grey(c.frame->right);
    }
    if (cfg_.refine == RefinerConfig::Method::match && cfg_.background.ratio > 0.0) {
      background_pixels_ += drop_background(c.left, c.right, *mask, cfg_.background);
      if (mask->count < cfg_.min_pixels) {
        ++no_pixels_;
        return std::nullopt;
      }
    }
    const std::optional<double> disparity =
        cfg_.refine == RefinerConfig::Method::mean
            ? robust_mean_disparity(*mask)
            : match_disparity(c.left, c.right, *mask, {cfg_.search_px, static_cast<int>(cfg_.iterations)});
    if (!disparity) {
      ++no_match_;
      return std::nullopt;
    }
    shift_sum_ += std::abs(*disparity - mask->sgbm_disparity);
    return centre_behind(place(calibration, *mask, *disparity), cfg_.centre_behind_surface_m);
  }

  RefinerConfig cfg_;
  std::deque<Capture> captures_;
  std::uint64_t detections_ = 0, refined_ = 0, no_capture_ = 0, no_pixels_ = 0, no_match_ = 0;
  std::uint64_t background_pixels_ = 0;
  double shift_sum_ = 0.0;
};
KESTREL_REGISTER_NODE(DisparityRefiner)

}  // namespace kestrel::refine
