#pragma once
// Coarse-to-fine matching of what stands out: the pair is matched at low resolution everywhere,
// and again at full resolution only inside the regions whose coarse disparity stands out of its
// background, each searched over its own few disparities. The objects then get full-resolution
// depth and a full-resolution foreground mask, at little more than the coarse match's cost.
#include <opencv2/core.hpp>
#include <vector>

#include "stereo_matching.hpp"

namespace kestrel::stereo {

struct FineRegionOptions {
  int margin_px = 8;            ///< full-resolution pixels added around each coarse object
  int disparity_margin_px = 4;  ///< full-resolution disparities searched beyond the object's coarse ones
};

/// A region matched at full resolution: its pixels, and the disparities searched there.
struct FineRegion {
  cv::Rect box;              ///< full-resolution pixels
  int min_disparity = 0;     ///< full-resolution pixels
  int num_disparities = 16;  ///< a multiple of 16
};

/// The connected parts of a coarse foreground mask (CV_8U, matched `factor` times smaller than
/// `full`), each grown by the margin and scaled to full-resolution pixels, with every disparity
/// the coarse pixels of that box hold, the background's too (`coarse_disparity`, CV_32F pixels,
/// 0 = none), scaled and widened by a coarse pixel and the disparity margin. Overlapping regions are merged, so no
/// pixel is matched twice.
std::vector<FineRegion> fine_regions(const cv::Mat& coarse_mask, const cv::Mat& coarse_disparity, int factor,
                                     cv::Size full, const FineRegionOptions& options);

/// The disparity (CV_16S, 1/16 px, negative = none) of `region.box` of a full-resolution grey
/// pair, matched with `options` over the region's disparities: the images are cropped to the box,
/// the columns its search reaches on the left, and the rows the block reaches above and below.
cv::Mat match_region(const GreyPair& pair, const FineRegion& region, MatcherOptions options);

}  // namespace kestrel::stereo
