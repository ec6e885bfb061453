// The `stereo_depth` node: disparity by OpenCV StereoSGBM (or StereoBM), reprojected to a
// camera-frame point cloud by the paper's equation (1).
#include <algorithm>
#include <kestrel/messages/point_cloud.hpp>
#include <kestrel/messages/stereo_frame.hpp>
#include <kestrel/plugin.hpp>
#include <opencv2/imgcodecs.hpp>

#include "stereo_matching.hpp"

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

  static NodeSpec spec() {
    return NodeSpec("stereo_depth", "Stereo disparity (OpenCV SGBM or BM) reprojected to a 3D point cloud")
        .details(
            "Each valid disparity d at pixel (u, v) becomes the point b/d * (u - cx, v - cy, f) in the left "
            "camera's optical frame (paper, equation 1), kept if its depth lies in [min_depth_m, max_depth_m]. "
            "With --report, frame `snapshot_frame` is saved as left.png and disparity.png.")
        .input(kFrame, "rectified stereo pair")
        .output(kCloud, "camera-frame points")
        .param(param("algorithm", std::string("sgbm")).one_of({"sgbm", "bm"}).describe("OpenCV matcher"))
        .param(param("mode", std::string("sgbm"))
                   .one_of({"sgbm", "hh", "sgbm_3way", "hh4"})
                   .describe("SGBM mode: 5 paths, full 8 paths, 3-way or 4-path HH"))
        .param(param("min_disparity", 0).range(-256, 256).with_unit("px").describe("smallest disparity searched"))
        .param(
            param("num_disparities", 112)
                .range(16, 1024)
                .with_unit("px")
                .describe("disparity search range, a multiple of 16 (112 reaches the oCamS's 0.5 m at fx 452, b 0.12)"))
        .param(param("block_size", 7).range(1, 51).with_unit("px").describe("matched block size, odd"))
        .param(param("p1", 0).at_least(0).describe(
            "SGBM smoothness penalty for +-1 disparity changes; 0 = 8 * block_size^2"))
        .param(param("p2", 0).at_least(0).describe("SGBM penalty for larger changes; 0 = 32 * block_size^2"))
        .param(param("uniqueness_ratio", 10).range(0, 100).with_unit("%").describe("best match margin over the second"))
        .param(param("speckle_window_size", 100)
                   .range(0, 10000)
                   .with_unit("px")
                   .describe("speckle filter region size; 0 = off"))
        .param(param("speckle_range", 2)
                   .range(0, 64)
                   .with_unit("px")
                   .describe("disparity variation within a speckle region"))
        .param(param("disp12_max_diff", 1)
                   .range(-1, 1024)
                   .with_unit("px")
                   .describe("left-right check tolerance; -1 = off"))
        .param(param("pre_filter_cap", 63).range(1, 255).describe("pre-filter clipping"))
        .param(param("texture_threshold", 10).range(0, 10000).describe("BM only: minimum texture"))
        .param(
            param("min_depth_m", 0.5).range(0.01, 1000.0).with_unit("m").describe("nearest point kept (oCamS: 0.5 m)"))
        .param(
            param("max_depth_m", 15.0).range(0.01, 1000.0).with_unit("m").describe("farthest point kept (oCamS: 15 m)"))
        .param(param("pixel_step", 1).range(1, 16).with_unit("px").describe("reproject every n-th pixel and row"))
        .param(param("downscale", 1)
                   .range(1, 8)
                   .describe("match on images shrunk by this factor (num_disparities is divided by it too): "
                             "faster, coarser depth"))
        .param(param("snapshot_frame", 30).at_least(-1).describe("frame index saved as PNG with --report; -1 = none"));
  }

  explicit StereoDepth(NodeInit& init)
      : min_depth_(init.param<double>("min_depth_m")),
        max_depth_(init.param<double>("max_depth_m")),
        step_(init.param<int>("pixel_step")),
        downscale_(init.param<int>("downscale")),
        snapshot_(init.param<std::int64_t>("snapshot_frame")) {
    options_.algorithm = init.param<std::string>("algorithm");
    options_.mode = init.param<std::string>("mode");
    options_.min_disparity = init.param<int>("min_disparity");
    // Disparities shrink with the images; keep OpenCV's multiple of 16.
    options_.num_disparities = std::max(16, (init.param<int>("num_disparities") / downscale_ + 15) / 16 * 16);
    options_.block_size = init.param<int>("block_size");
    options_.p1 = init.param<int>("p1");
    options_.p2 = init.param<int>("p2");
    options_.uniqueness_ratio = init.param<int>("uniqueness_ratio");
    options_.speckle_window_size = init.param<int>("speckle_window_size");
    options_.speckle_range = init.param<int>("speckle_range");
    options_.disp12_max_diff = init.param<int>("disp12_max_diff");
    options_.pre_filter_cap = init.param<int>("pre_filter_cap");
    options_.texture_threshold = init.param<int>("texture_threshold");
    if (min_depth_ >= max_depth_) throw Error("min_depth_m must be below max_depth_m");
    matcher_ = make_matcher(options_);
  }

  void process(Context& ctx) override {
    const auto frame = ctx.get(kFrame);
    const ScaledPair pair = downscale(frame->left, frame->right, frame->calibration, downscale_);
    const cv::Mat disparity = compute_disparity(*matcher_, pair.left, pair.right);
    msg::PointCloud cloud;
    cloud.stamp = frame->stamp;
    cloud.frame = "camera";
    cloud.points = reproject(disparity, pair.calibration, min_depth_, max_depth_, step_);
    if (static_cast<std::int64_t>(frame->frame_index) == snapshot_ && ctx.keeps_artifacts()) {
      ctx.add_artifact("left.png", encode_png(frame->left), "left image");
      ctx.add_artifact("right.png", encode_png(frame->right), "right image");
      ctx.add_artifact("disparity.png", encode_png(colourise_disparity(disparity, options_.num_disparities)),
                       "disparity (near is warm)");
    }
    ctx.publish(kCloud, std::move(cloud));
  }

 private:
  MatcherOptions options_;
  double min_depth_, max_depth_;
  int step_;
  int downscale_;
  std::int64_t snapshot_;
  cv::Ptr<cv::StereoMatcher> matcher_;
};
KESTREL_REGISTER_NODE(StereoDepth)

}  // namespace kestrel::stereo
