#pragma once
// Coarse-to-fine matching of what stands out: the pair is matched at low resolution everywhere,
// and again at full resolution only inside the regions whose coarse disparity stands out of its
// background. The objects then get full-resolution depth and a full-resolution foreground mask,
// at little more than the coarse match's cost.
#include <opencv2/core.hpp>
#include <vector>

#include "foreground_mask.hpp"
#include "stereo_matching.hpp"

namespace kestrel::stereo {

/// The connected parts of a coarse foreground mask (CV_8U, matched `factor` times smaller than
/// `full`), as boxes of full-resolution pixels grown by `margin_px` on every side and cut to the
/// image. Overlapping boxes are merged, so no pixel is matched twice.
std::vector<cv::Rect> fine_regions(const cv::Mat& coarse_mask, int factor, cv::Size full, int margin_px);

/// The disparity (CV_16S, 1/16 px, negative = none) of `box` of a full-resolution grey pair,
/// matched with `options` (all their disparities, as on the whole image) on the images cropped to
/// the box, the columns its search reaches on the left, and a run-in for SGBM's paths: inside the
/// box it is what matching the whole pair gives there, up to the paths' start.
cv::Mat match_region(const GreyPair& pair, const cv::Rect& box, const MatcherOptions& options);

/// What `match_region` matched: the whole crop's disparity (CV_16S, 1/16 px; its first
/// min_disparity + num_disparities columns hold no match) and where the box lies in it.
struct RegionMatch {
  cv::Mat disparity16;
  cv::Rect box;
};
RegionMatch match_region_crop(const GreyPair& pair, const cv::Rect& box, const MatcherOptions& options);

/// The foreground mask (CV_8U) of a region's box, matched at full resolution: `crop` is the crop's
/// disparity (CV_32F pixels, 0 = no match) and `box` the box in it, at `box_origin` in the image.
/// Each pixel stands out by `standing_out_threshold` in front of the background behind it: the
/// coarse map's (matched `factor` times smaller) and, where given and it sees the pixel, the crop's
/// own (`own`), whichever is nearer. Then opened by `options.min_thickness_px`.
cv::Mat region_foreground(const cv::Mat& crop, const cv::Rect& box, cv::Point box_origin, int factor,
                          const DisparityBackground& coarse, const DisparityBackground* own, double focal_baseline,
                          const ForegroundOptions& options);

}  // namespace kestrel::stereo
