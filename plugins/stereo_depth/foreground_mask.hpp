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
#include <optional>
#include <vector>

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

class DisparityBackground;

/// The same for a map already converted (`disparity_unmatched_far`) whose background is already
/// built, for a caller that judges other pixels against that background too.
cv::Mat foreground_mask(const cv::Mat& disparity, const DisparityBackground& background,
                        const msg::StereoCalibration& calibration, const ForegroundOptions& options);

/// A CV_16S disparity map (1/16 px) as CV_32F pixels, no match (<= 0) as 0: infinitely far.
cv::Mat disparity_unmatched_far(const cv::Mat& disparity16);

/// The background of a disparity map (CV_32F pixels, 0 = no match): for each pixel, and for the
/// disparity an object there would have, the larger of the two openings (down the column and along
/// the row) whose windows are longer than such an object. foreground_mask judges the map's own
/// pixels against it; coarse-to-fine matching judges full-resolution pixels against the background
/// of the coarse map.
class DisparityBackground {
 public:
  DisparityBackground(const cv::Mat& disparity, const msg::StereoCalibration& calibration,
                      const ForegroundOptions& options);
  /// False for the unseen columns on the left (outside the picture).
  bool sees(int col) const { return col >= first_ && col < cols_; }
  int rows() const { return rows_; }
  int cols() const { return cols_; }
  /// The background's disparity behind pixel (row, col) of the map for an object of disparity d
  /// there; `col` must be seen.
  float behind(int row, int col, float d) const;

 private:
  // Openings down the columns of a map at radii 1, 2, 4, ... up to what a pixel of the largest
  // disparity needs: an object of size S at disparity d spans S * d * pixels_per_disparity / S
  // pixels, and a window of 2r + 1 pixels fits in it no more once 2r + 1 exceeds that.
  struct Openings {
    double pixels_per_disparity = 0.0;
    std::vector<int> radii;
    std::vector<cv::Mat> images;
    Openings(const cv::Mat& disparity, double max_disparity, double pixels_per_disparity);
    int radius_for(double d) const;
    // The opening at (row, col) with the smallest window tall enough for disparity d.
    float at(int row, int col, float d) const;
  };
  int first_ = 0, rows_ = 0, cols_ = 0, k_ = 1;
  std::optional<Openings> down_, across_;
};

/// How far (px) a pixel of disparity d must stand in front of its background: gap_m in depth,
/// and at least min_step_px.
double standing_out_threshold(double d, double focal_baseline, const ForegroundOptions& options);

/// Opens a CV_8U mask by a square of `min_thickness_px` (1 or less: unchanged).
void open_thin_parts(cv::Mat& mask, int min_thickness_px);

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
