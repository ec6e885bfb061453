#include "depth_pipeline.hpp"

#include <opencv2/core/utility.hpp>
#include <optional>

#include "kestrel/error.hpp"

namespace kestrel::stereo {

DepthPipeline::DepthPipeline(const MatcherOptions& matcher, const ForegroundOptions& foreground,
                             const DepthOptions& options)
    : matcher_(matcher), foreground_(foreground), options_(options) {
  if (options.fine_regions && (options.downscale < 2 || foreground.gap_m <= 0.0))
    throw Error("fine_regions needs downscale > 1 and the foreground segmentation (foreground_gap_m > 0)");
  coarse_matcher_options_ = options_for_downscale(matcher, options.downscale);
  if (options.downscale > 1 && options.coarse_block_size > 0)
    coarse_matcher_options_.block_size = options.coarse_block_size;
  const int strips = options.strips > 0 ? options.strips : (is_five_path_sgbm(coarse_matcher_options_) ? 2 : 1);
  matcher_strips_.emplace(coarse_matcher_options_, strips,
                          (options.strip_overlap_px + options.downscale - 1) / options.downscale);
  coarse_foreground_ = options_for_downscale(foreground, options.downscale, coarse_matcher_options_);
  // Regions are candidates, judged again at full resolution: the coarse map flags a step as small
  // as the full-resolution one (min_step_px is in the matched map's pixels), and keeps parts
  // thinner than the full-resolution mask would (an intruder against trees is a thin sliver in
  // the coarse map).
  if (options.fine_regions) coarse_foreground_.min_step_px /= options.downscale;
  if (options.fine_regions) coarse_foreground_.min_thickness_px = options.fine_candidate_thickness_px;
  region_foreground_ = options_for_downscale(foreground, 1, matcher);
}

DepthResult DepthPipeline::compute(const cv::Mat& left, const cv::Mat& right, const msg::StereoCalibration& c) {
  const ScaledPair pair = downscale(left, right, c, options_.downscale);
  DepthResult result;
  result.disparity = matcher_strips_->compute(pair.left, pair.right);
  const bool segment = coarse_foreground_.gap_m > 0.0;
  std::optional<DisparityBackground> background;
  if (segment) {
    const cv::Mat disparity = disparity_unmatched_far(result.disparity);
    background.emplace(disparity, pair.calibration, coarse_foreground_);
    result.foreground = foreground_mask(disparity, *background, pair.calibration, coarse_foreground_);
  }
  const auto sampled = [&](int n) {
    return static_cast<std::uint64_t>((n + options_.pixel_step - 1) / options_.pixel_step);
  };
  if (!options_.fine_regions) {
    result.points = reproject(result.disparity, pair.calibration, options_.min_depth_m, options_.max_depth_m,
                              options_.pixel_step, result.foreground);
    result.pixels_per_point = options_.downscale * options_.pixel_step;
    result.focal_baseline_px_m = pair.calibration.fx * pair.calibration.baseline_m;
    result.pixels_sampled = sampled(result.disparity.rows) * sampled(result.disparity.cols);
    return result;
  }
  result.points = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  add_fine_regions(grey_pair(left, right), c, *background, result);
  result.pixels_per_point = options_.pixel_step;
  result.focal_baseline_px_m = c.fx * c.baseline_m;
  result.pixels_sampled = sampled(left.rows) * sampled(left.cols);
  return result;
}

void DepthPipeline::add_fine_regions(const GreyPair& full, const msg::StereoCalibration& c,
                                     const DisparityBackground& coarse_background, DepthResult& result) const {
  const int f = options_.downscale;
  const std::vector<cv::Rect> regions = fine_regions(result.foreground, f, full.left.size(), options_.fine_margin_px);
  std::vector<pcl::PointCloud<pcl::PointXYZ>::Ptr> parts(regions.size());
  const double fb = c.fx * c.baseline_m;
  cv::parallel_for_(cv::Range(0, static_cast<int>(regions.size())), [&](const cv::Range& range) {
    for (int i = range.start; i < range.end; ++i) {
      const cv::Rect& region = regions[static_cast<std::size_t>(i)];
      const RegionMatch match = match_region_crop(full, region, matcher_);
      const cv::Mat crop = disparity_unmatched_far(match.disparity16);
      // The full-resolution pixels are judged against the coarse map's background (the objects
      // have gone from it, and it reaches beyond the region) and, where the region's own map has
      // one, against that: what matched only at full resolution is its own background there.
      std::optional<DisparityBackground> own;
      if (options_.fine_region_background) own.emplace(crop, c, region_foreground_);
      const cv::Mat mask =
          region_foreground(crop, match.box, region.tl(), f, coarse_background, own ? &*own : nullptr, fb, foreground_);
      msg::StereoCalibration shifted = c;
      shifted.cx -= region.x;
      shifted.cy -= region.y;
      parts[static_cast<std::size_t>(i)] = reproject(match.disparity16(match.box), shifted, options_.min_depth_m,
                                                     options_.max_depth_m, options_.pixel_step, mask);
    }
  });
  for (const auto& part : parts) *result.points += *part;
  result.regions = static_cast<int>(regions.size());
  for (const cv::Rect& r : regions) result.region_pixels += static_cast<std::uint64_t>(r.area());
}

}  // namespace kestrel::stereo
