// The `stereo_depth` node: disparity by OpenCV StereoSGBM (or StereoBM), reprojected to a
// camera-frame point cloud by the paper's equation (1).
#include <fmt/format.h>

#include <algorithm>
#include <kestrel/messages/point_cloud.hpp>
#include <kestrel/messages/stereo_frame.hpp>
#include <kestrel/plugin.hpp>
#include <opencv2/imgcodecs.hpp>

#include "depth_pipeline.hpp"
#include "depth_statistics.hpp"

namespace kestrel::stereo {

namespace {
std::string encode_png(const cv::Mat& image) {
  std::vector<unsigned char> bytes;
  if (!cv::imencode(".png", image, bytes)) throw Error("cannot encode a snapshot as PNG");
  return {bytes.begin(), bytes.end()};
}
}  // namespace

class StereoDepth final : public Node {
 public:
  static constexpr Input<msg::StereoFrame> kFrame{"frame"};
  static constexpr Output<msg::PointCloud> kCloud{"cloud"};

  struct Config {
    MatcherOptions matcher;
    ForegroundOptions foreground;
    DepthOptions depth;
    std::int64_t snapshot_frame = 30;
  };

  static NodeSpec spec() {
    using M = MatcherOptions;
    ConfigSpec<Config> c;
    c.choice("algorithm", &Config::matcher, &M::algorithm, {{"sgbm", M::Algorithm::sgbm}, {"bm", M::Algorithm::bm}})
        .describe("OpenCV matcher");
    c.choice("mode", &Config::matcher, &M::mode,
             {{"sgbm", M::Mode::sgbm}, {"hh", M::Mode::hh}, {"sgbm_3way", M::Mode::sgbm_3way}, {"hh4", M::Mode::hh4}})
        .describe("SGBM mode: 5 paths, full 8 paths, 3-way or 4-path HH");
    c.param("min_disparity", &Config::matcher, &M::min_disparity)
        .range(-256, 256)
        .with_unit("px")
        .describe("smallest disparity searched");
    c.param("num_disparities", &Config::matcher, &M::num_disparities)
        .range(16, 1024)
        .with_unit("px")
        .describe("disparity search range, a multiple of 16 (112 reaches the oCamS's 0.5 m at fx 452, b 0.12)");
    c.param("block_size", &Config::matcher, &M::block_size)
        .range(1, 51)
        .with_unit("px")
        .describe("matched block size, odd");
    c.param("p1", &Config::matcher, &M::p1)
        .at_least(0)
        .describe("SGBM smoothness penalty for +-1 disparity changes; 0 = 8 * block_size^2");
    c.param("p2", &Config::matcher, &M::p2)
        .at_least(0)
        .describe("SGBM penalty for larger changes; 0 = 32 * block_size^2");
    c.param("uniqueness_ratio", &Config::matcher, &M::uniqueness_ratio)
        .range(0, 100)
        .with_unit("%")
        .describe("best match margin over the second");
    c.param("speckle_window_size", &Config::matcher, &M::speckle_window_size)
        .range(0, 10000)
        .with_unit("px")
        .describe("speckle filter region size, in full-resolution pixels (divided by downscale^2); 0 = off");
    c.param("speckle_range", &Config::matcher, &M::speckle_range)
        .range(0, 64)
        .with_unit("px")
        .describe("disparity variation within a speckle region");
    c.param("disp12_max_diff", &Config::matcher, &M::disp12_max_diff)
        .range(-1, 1024)
        .with_unit("px")
        .describe("left-right check tolerance; -1 = off");
    c.param("pre_filter_cap", &Config::matcher, &M::pre_filter_cap).range(1, 255).describe("pre-filter clipping");
    c.param("texture_threshold", &Config::matcher, &M::texture_threshold)
        .range(0, 10000)
        .describe("BM only: minimum texture");
    c.param("min_depth_m", &Config::depth, &DepthOptions::min_depth_m)
        .range(0.01, 1000.0)
        .with_unit("m")
        .describe("nearest point kept (oCamS: 0.5 m)");
    c.param("max_depth_m", &Config::depth, &DepthOptions::max_depth_m)
        .range(0.01, 1000.0)
        .with_unit("m")
        .describe("farthest point kept (oCamS: 15 m)");
    c.param("pixel_step", &Config::depth, &DepthOptions::pixel_step)
        .range(1, 16)
        .with_unit("px")
        .describe("reproject every n-th pixel and row");
    c.param("downscale", &Config::depth, &DepthOptions::downscale)
        .range(1, 8)
        .describe(
            "match on images shrunk by this factor (num_disparities is divided by it too): faster, coarser depth. "
            "With a disparity_refiner after the clusters this is coarse-to-fine: the objects are found at low "
            "resolution and their disparity measured at full resolution");
    c.param("coarse_block_size", &Config::depth, &DepthOptions::coarse_block_size)
        .range(0, 51)
        .with_unit("px")
        .describe(
            "with downscale > 1: the block matched on the shrunk images, odd; 0 = block_size (a smaller block keeps "
            "a far object that is a few coarse pixels tall; p1 and p2 at 0 follow it)");
    c.param("strips", &Config::depth, &DepthOptions::strips)
        .range(0, 16)
        .describe(
            "match the pair as this many horizontal strips in parallel (SGBM mode sgbm only; 1 = OpenCV's matcher on "
            "the whole image; 0 = 2 in mode sgbm, for two cores, else 1): the top strip is exactly the whole image's "
            "result, the others start strip_overlap_px higher so that SGBM's paths from above reach them");
    c.param("strip_overlap_px", &Config::depth, &DepthOptions::strip_overlap_px)
        .range(0, 1000)
        .with_unit("px")
        .describe("rows matched above each strip but the first and then dropped, in full-resolution pixels");
    c.param("fine_regions", &Config::depth, &DepthOptions::fine_regions)
        .describe(
            "with downscale > 1 and foreground_gap_m > 0: match each region that stands out in the coarse map again "
            "at full resolution, and take its points and its foreground mask from there (coarse-to-fine matching: "
            "full-resolution objects at little more than the coarse cost)");
    c.param("fine_margin_px", &Config::depth, &DepthOptions::fine_margin_px)
        .range(0, 200)
        .with_unit("px")
        .describe("fine_regions: full-resolution pixels matched around each coarse object");
    c.param("fine_candidate_thickness_px", &Config::depth, &DepthOptions::fine_candidate_thickness_px)
        .range(1, 31)
        .with_unit("px")
        .describe(
            "fine_regions: the coarse mask's parts thinner than this (coarse pixels) are no candidates; the "
            "full-resolution mask is then opened by foreground_min_thickness_px");
    c.param("fine_region_background", &Config::depth, &DepthOptions::fine_region_background)
        .describe(
            "fine_regions: judge a region's full-resolution pixels against its own full-resolution map's background "
            "too, not only the coarse map's (leaves the coarse match missed stand out of the sky behind them)");
    c.param("foreground_gap_m", &Config::foreground, &ForegroundOptions::gap_m)
        .range(0.0, 100.0)
        .with_unit("m")
        .describe(
            "keep only points that stand at least this far in front of what is above and below them, and of what "
            "is left and right of them (top-hats of the disparity), which cuts an intruder from the trees behind "
            "it; 0 keeps every point (the paper)");
    c.param("foreground_min_step_px", &Config::foreground, &ForegroundOptions::min_step_px)
        .range(0.0, 100.0)
        .with_unit("px")
        .describe(
            "foreground: and at least this much nearer in disparity, so that matching's noise on a distant surface "
            "does not stand out (at fx = 304 px and b = 0.12 m, a 0.5 m step in depth at 4.5 m is 0.8 px); in the "
            "pixels of the images matched (downscale)");
    c.param("foreground_max_height_m", &Config::foreground, &ForegroundOptions::max_height_m)
        .range(0.01, 100.0)
        .with_unit("m")
        .describe("foreground: the tallest object that can stand out; taller ones (trunks, walls) are background");
    c.param("foreground_max_width_m", &Config::foreground, &ForegroundOptions::max_width_m)
        .range(0.01, 100.0)
        .with_unit("m")
        .describe("foreground: the widest object that can stand out; wider ones (canopies, walls) are background");
    c.param("foreground_min_thickness_px", &Config::foreground, &ForegroundOptions::min_thickness_px)
        .range(1, 31)
        .with_unit("px")
        .describe(
            "foreground: parts thinner than this, in full-resolution pixels (slivers that matching leaves along the "
            "edges of trees), are taken out by an opening of the mask; 1 keeps them");
    c.param("foreground_max_hole_px", &Config::foreground, &ForegroundOptions::max_hole_px)
        .range(0, 1000)
        .with_unit("px")
        .describe(
            "foreground: runs of unmatched pixels up to this long (full-resolution pixels) between matched ones are "
            "holes in a surface, not a view through it (longer runs, such as the sky, count as far); 0 counts every "
            "one as far");
    c.param("snapshot_frame", &Config::snapshot_frame)
        .at_least(-1)
        .describe("frame index saved as PNG with --report; -1 = none");
    // What OpenCV would refuse, or silently change, said before the run.
    c.rule("min_depth_m < max_depth_m", {"min_depth_m", "max_depth_m"},
           [](const Config& k) { return k.depth.min_depth_m < k.depth.max_depth_m; });
    c.rule("num_disparities is a multiple of 16", {"num_disparities"},
           [](const Config& k) { return k.matcher.num_disparities % 16 == 0; });
    c.rule(
        "fine_regions needs downscale > 1 and foreground_gap_m > 0", {"fine_regions", "downscale", "foreground_gap_m"},
        [](const Config& k) { return !k.depth.fine_regions || (k.depth.downscale > 1 && k.foreground.gap_m > 0.0); });
    c.rule("block_size is odd", {"block_size"}, [](const Config& k) { return k.matcher.block_size % 2 == 1; });
    c.rule("coarse_block_size is 0 or odd", {"coarse_block_size"},
           [](const Config& k) { return k.depth.coarse_block_size == 0 || k.depth.coarse_block_size % 2 == 1; });
    c.rule("block_size >= 5 for algorithm bm", {"block_size", "algorithm"},
           [](const Config& k) { return k.matcher.algorithm != M::Algorithm::bm || k.matcher.block_size >= 5; });
    c.rule("pre_filter_cap <= 63 for algorithm bm", {"pre_filter_cap", "algorithm"},
           [](const Config& k) { return k.matcher.algorithm != M::Algorithm::bm || k.matcher.pre_filter_cap <= 63; });
    c.rule(
        "strips > 1 only with algorithm sgbm in mode sgbm (the other modes aggregate from below, or run in "
        "parallel already)",
        {"strips", "algorithm", "mode"},
        [](const Config& k) { return k.depth.strips <= 1 || is_five_path_sgbm(k.matcher); });
    c.rule("p2 > p1 for algorithm sgbm (0 = 8 and 32 * block_size^2)", {"p2", "p1", "block_size", "algorithm"},
           [](const Config& k) {
             const int area = k.matcher.block_size * k.matcher.block_size;
             const int p1 = k.matcher.p1 > 0 ? k.matcher.p1 : 8 * area;
             const int p2 = k.matcher.p2 > 0 ? k.matcher.p2 : 32 * area;
             return k.matcher.algorithm != M::Algorithm::sgbm || p2 > p1;
           });
    return NodeSpec("stereo_depth", "Stereo disparity (OpenCV SGBM or BM) reprojected to a 3D point cloud")
        .details(
            "Each valid disparity d at pixel (u, v) becomes the point b/d * (u - cx, v - cy, f) in the left "
            "camera's optical frame (paper, equation 1), kept if its depth lies in [min_depth_m, max_depth_m]. "
            "With --report, frame `snapshot_frame` is saved as left.png, right.png and disparity.png.")
        .input(kFrame, "rectified stereo pair")
        .output(kCloud, "camera-frame points")
        .config(std::move(c));
  }

  explicit StereoDepth(NodeInit& init)
      : cfg_(init.config<Config>()), pipeline_(cfg_.matcher, cfg_.foreground, cfg_.depth) {}

  void process(Context& ctx) override {
    const auto frame = ctx.get(kFrame);
    DepthResult depth = pipeline_.compute(frame->left, frame->right, frame->calibration);
    msg::PointCloud cloud;
    cloud.stamp = frame->stamp;
    cloud.frame = "camera";
    cloud.points = depth.points;
    cloud.pixels_per_point = depth.pixels_per_point;
    cloud.focal_baseline_px_m = depth.focal_baseline_px_m;
    if (static_cast<std::int64_t>(frame->frame_index) == cfg_.snapshot_frame && ctx.keeps_artifacts()) {
      ctx.add_artifact("left.png", encode_png(frame->left), "left image");
      ctx.add_artifact("right.png", encode_png(frame->right), "right image");
      ctx.add_artifact("disparity.png",
                       encode_png(colourise_disparity(depth.disparity, pipeline_.matched_disparities())),
                       "disparity (near is warm)");
      if (!depth.foreground.empty())
        ctx.add_artifact("foreground.png", encode_png(depth.foreground),
                         "foreground: what stands in front of its background");
    }
    statistics_.add_frame(*cloud.points, depth.pixels_sampled);
    regions_ += static_cast<std::uint64_t>(depth.regions);
    region_pixels_ += depth.region_pixels;
    full_pixels_ += static_cast<std::uint64_t>(frame->left.total());
    ctx.publish(kCloud, std::move(cloud));
  }

  void finish(Context& ctx) override {
    const auto depth = [&](double fraction) {
      const auto d = statistics_.percentile(fraction);
      return d ? nlohmann::json(*d) : nlohmann::json();
    };
    ReportSection section;
    if (cfg_.depth.fine_regions) {
      const double frames = std::max<double>(1.0, static_cast<double>(statistics_.frames()));
      section.quantity("fine_regions_per_frame", static_cast<double>(regions_) / frames)
          .quantity("fine_pixel_fraction",
                    full_pixels_ ? static_cast<double>(region_pixels_) / static_cast<double>(full_pixels_) : 0.0);
    }
    ctx.set_report_section(
        ctx.id(),
        section.quantity("frames", statistics_.frames())
            .quantity("points_per_frame", statistics_.points_per_frame())
            .quantity("valid_fraction", statistics_.valid_fraction())
            .quantity("depth_m", nlohmann::json{{"p5", depth(0.05)}, {"p50", depth(0.5)}, {"p95", depth(0.95)}}, "m")
            .markdown(fmt::format("{} frame(s), {:.0f} points a frame ({:.1f} % of the pixels matched).\n",
                                  statistics_.frames(), statistics_.points_per_frame(),
                                  100.0 * statistics_.valid_fraction())));
  }

 private:
  Config cfg_;
  DepthPipeline pipeline_;
  DepthStatistics statistics_{cfg_.depth.min_depth_m, cfg_.depth.max_depth_m};
  std::uint64_t regions_ = 0, region_pixels_ = 0, full_pixels_ = 0;
};
KESTREL_REGISTER_NODE(StereoDepth)

}  // namespace kestrel::stereo
