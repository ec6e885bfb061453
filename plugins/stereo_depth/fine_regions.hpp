#pragma once
// Coarse-to-fine matching of what stands out: the pair is matched at low resolution everywhere,
// and again at full resolution only inside the regions whose coarse disparity stands out of its
// background. The objects then get full-resolution depth and a full-resolution foreground mask,
// at little more than the coarse match's cost.
#include <opencv2/core.hpp>
#include <vector>

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

}  // namespace kestrel::stereo
