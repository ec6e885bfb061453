#pragma once
// Stereo matching and reprojection: OpenCV's StereoSGBM (or StereoBM) for disparity, and the
// paper's equation (1) to turn valid disparities into camera-frame points.
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <opencv2/calib3d.hpp>
#include <string>

#include "kestrel/messages/stereo_frame.hpp"

namespace kestrel::stereo {

struct MatcherOptions {
  /// OpenCV's semi-global matcher (the paper's) or its block matcher.
  enum class Algorithm { sgbm, bm };
  /// SGBM's aggregation: 5 paths, full 8 paths (HH), 3-way, or 4-path HH.
  enum class Mode { sgbm, hh, sgbm_3way, hh4 };

  Algorithm algorithm = Algorithm::sgbm;
  Mode mode = Mode::sgbm;  ///< SGBM only
  int min_disparity = 0;
  int num_disparities = 112;  ///< multiple of 16
  int block_size = 7;         ///< odd
  int p1 = 0;                 ///< 0: 8 * block_size^2
  int p2 = 0;                 ///< 0: 32 * block_size^2
  int uniqueness_ratio = 10;
  int speckle_window_size = 100;
  int speckle_range = 2;
  int disp12_max_diff = 1;
  int pre_filter_cap = 63;
  int texture_threshold = 10;  ///< BM only
};

/// True for OpenCV's default 5-path SGBM, the only mode that can run in strips.
inline bool is_five_path_sgbm(const MatcherOptions& o) {
  return o.algorithm == MatcherOptions::Algorithm::sgbm && o.mode == MatcherOptions::Mode::sgbm;
}

/// Throws kestrel::Error if the options are not ones OpenCV accepts.
cv::Ptr<cv::StereoMatcher> make_matcher(const MatcherOptions& options);

/// A rectified pair as the matchers take it: checked (same size and type, 8-bit grey or BGR;
/// kestrel::Error otherwise) and grey (BGR converted, grey shared, not copied).
struct GreyPair {
  cv::Mat left, right;
};
GreyPair grey_pair(const cv::Mat& left, const cv::Mat& right);

/// Disparity of a rectified pair (8-bit grey or BGR): CV_16S, in 1/16 pixel, negative = invalid.
cv::Mat compute_disparity(cv::StereoMatcher& matcher, const cv::Mat& left, const cv::Mat& right);

/// Equation (1): for each valid disparity d (pixels) at (u, v),
///   [X Y Z] = b / d * [u - cx, v - cy, f],
/// kept if min_depth <= Z <= max_depth. `step` samples every step-th pixel in each direction.
/// A non-empty CV_8U `mask` keeps only its non-zero pixels.
pcl::PointCloud<pcl::PointXYZ>::Ptr reproject(const cv::Mat& disparity16, const msg::StereoCalibration& calibration,
                                              double min_depth, double max_depth, int step = 1,
                                              const cv::Mat& mask = {});

/// The pair and its calibration shrunk by an integer factor (area averaging), so that matching
/// runs on factor^2 fewer pixels with factor times fewer disparities.
struct ScaledPair {
  cv::Mat left, right;
  msg::StereoCalibration calibration;
};
ScaledPair downscale(const cv::Mat& left, const cv::Mat& right, const msg::StereoCalibration& calibration, int factor);

/// The matcher's options for images shrunk by `factor`: disparities shrink with the images (kept a
/// multiple of 16, as OpenCV needs), speckle regions with the area (a drone of 100 pixels is 25
/// at half resolution, not a speckle).
MatcherOptions options_for_downscale(MatcherOptions options, int factor);

/// A disparity map as a colour image for people (invalid pixels black).
cv::Mat colourise_disparity(const cv::Mat& disparity16, int num_disparities);

}  // namespace kestrel::stereo
