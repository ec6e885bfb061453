#pragma once
// Segments small objects against what stands behind them before any clustering: a pixel is
// foreground when its disparity stands out, by a depth gap, above the background found by
// grey-level openings of the disparity map (top-hats) down its column and along its row. Each
// opening's window grows with the pixel's disparity, so that it is always longer than an object
// of max_height_m (down) or max_width_m (along) at that depth: such objects (a drone, a bird)
// vanish from both openings and stand out, while what is taller (trunks, the ground's slope) or
// wider (canopies, walls) is its own background in one of them and does not. An intruder in
// front of a tree a metre behind it is so cut from the tree, which Euclidean clusters at 0.5 m
// would merge with it. The background is found on the map subsampled to 320 columns or fewer;
// each pixel is then judged at full resolution against it.
#include <opencv2/core.hpp>

#include "kestrel/messages/stereo_frame.hpp"
#include "stereo_matching.hpp"

namespace kestrel::stereo {

struct ForegroundOptions {
  double gap_m = 0.0;         ///< how far in front of its background a pixel must stand; 0: off
  double min_step_px = 0.8;   ///< and at least this much disparity: above matching's noise at range
  double max_height_m = 0.5;  ///< the tallest object separated
  double max_width_m = 1.0;   ///< the widest
  int min_thickness_px = 7;   ///< thinner parts of the mask (slivers along edges) are taken out
  int max_hole_px = 16;       ///< shorter runs without a match, inside a surface, take the surface's depth
  /// Columns on the left the right camera does not see (the matcher's min_disparity +
  /// num_disparities): outside the picture, so what touches them is not judged against them.
  int unseen_left_columns = 0;
};

/// The options for a disparity map matched on images shrunk by `factor` with `matcher`'s (already
/// shrunk) disparities: thickness and holes are given in full-resolution pixels and shrink with
/// the images; the disparity step stays in the matched image's pixels (matching's noise is a
/// fraction of its own pixels).
ForegroundOptions options_for_downscale(ForegroundOptions options, int factor, const MatcherOptions& matcher);

/// CV_8U mask of `disparity16` (CV_16S, 1/16 px, <= 0 invalid): 255 where a valid pixel stands
/// gap_m (and min_step_px) or more in front of both openings of the disparity (invalid counting
/// as infinitely far, short holes filled, the unseen left columns outside the picture),
/// then opened by a square of min_thickness_px: the slivers that matching leaves along the edges of
/// trees go, a solid object's body stays.
cv::Mat foreground_mask(const cv::Mat& disparity16, const msg::StereoCalibration& calibration,
                        const ForegroundOptions& options);

/// Fills each run of at most `max_run` zero (no match) pixels down the columns of a CV_32F map that
/// has non-zero pixels at both ends with the smaller (farther) of the two: a hole in a surface is
/// not a view through it. Longer runs (the sky) stay.
void fill_short_holes_down(cv::Mat& disparity, int max_run);

/// Running minimum (erode) or maximum (dilate) over the 2 * radius + 1 rows centred on each row of
/// a CV_32F image, rows outside the image ignored. Three comparisons a pixel whatever the radius
/// (van Herk / Gil-Werman), row by row so that the compiler vectorises across columns.
cv::Mat vertical_erode(const cv::Mat& image, int radius);
cv::Mat vertical_dilate(const cv::Mat& image, int radius);

}  // namespace kestrel::stereo
