#pragma once
// stereo_depth's work on one pair, shared by the node and the benchmarks: match (on shrunk images
// with `downscale`, in strips), segment the foreground, optionally match the foreground's regions
// again at full resolution (coarse-to-fine), and reproject to camera-frame points.
#include <cstdint>
#include <optional>

#include "fine_regions.hpp"
#include "foreground_mask.hpp"
#include "stereo_matching.hpp"
#include "striped_matcher.hpp"

namespace kestrel::stereo {

struct DepthOptions {
  double min_depth_m = 0.5;  ///< the oCamS's range: 0.5 to 15 m
  double max_depth_m = 15.0;
  int pixel_step = 1;
  int downscale = 1;
  int strips = 0;  ///< 0: 2 for 5-path SGBM, else 1
  /// The block matched on shrunk images (downscale > 1); 0: the matcher's block_size. A smaller
  /// block keeps a far object that is a few coarse pixels tall.
  int coarse_block_size = 0;
  int strip_overlap_px = 48;
  /// With downscale > 1 and the foreground segmentation on: match each region that stands out
  /// again at full resolution, and take its points (and its mask) from there.
  bool fine_regions = false;
  int fine_margin_px = 8;
  int fine_candidate_thickness_px = 2;  ///< the coarse candidates' opening, in coarse pixels
  /// Judge a region's full-resolution pixels also against the background of the region's own
  /// full-resolution map, not only the coarse map's: where the coarse match found nothing (a
  /// canopy's leaves), the coarse background is the sky, and the leaves matched at full
  /// resolution would stand out of it.
  bool fine_region_background = true;
};

struct DepthResult {
  pcl::PointCloud<pcl::PointXYZ>::Ptr points;
  cv::Mat disparity;   ///< as matched (CV_16S, 1/16 px), at the matched (coarse) resolution
  cv::Mat foreground;  ///< the matched map's foreground mask (empty without the segmentation)
  int pixels_per_point = 1;
  double focal_baseline_px_m = 0.0;  ///< of the pixels the points come from
  std::uint64_t pixels_sampled = 0;  ///< pixels that could have become points
  int regions = 0;                   ///< regions matched again at full resolution
  std::uint64_t region_pixels = 0;   ///< their pixels
};

class DepthPipeline {
 public:
  /// Throws kestrel::Error for options OpenCV would refuse.
  DepthPipeline(const MatcherOptions& matcher, const ForegroundOptions& foreground, const DepthOptions& options);

  DepthResult compute(const cv::Mat& left, const cv::Mat& right, const msg::StereoCalibration& calibration);

  /// Disparities searched on the matched images.
  int matched_disparities() const { return coarse_matcher_options_.num_disparities; }

 private:
  void add_fine_regions(const GreyPair& full, const msg::StereoCalibration& calibration,
                        const DisparityBackground& coarse_background, DepthResult& result) const;

  MatcherOptions matcher_;
  ForegroundOptions foreground_;         // as given, for full-resolution pixels
  ForegroundOptions region_foreground_;  // for a region's crop matched at full resolution (its search columns unseen)
  MatcherOptions coarse_matcher_options_;
  ForegroundOptions coarse_foreground_;  // for the matched (coarse) map
  DepthOptions options_;
  std::optional<StripedMatcher> matcher_strips_;
};

}  // namespace kestrel::stereo
