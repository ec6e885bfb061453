#pragma once
// A disparity map against ground truth, as the Middlebury benchmark scores it: on the pixels the
// truth knows, the share a matcher left without a disparity, the share off by more than 1 and
// 2 px (bad-1, bad-2) among those it matched, and the median error.
#include <filesystem>
#include <opencv2/core.hpp>

namespace kestrel::stereo {

struct DisparityScore {
  std::size_t known = 0;         ///< pixels with a true disparity
  std::size_t matched = 0;       ///< of those, with an estimate
  double bad1 = 0.0;             ///< share of matched pixels off by more than 1 px
  double bad2 = 0.0;             ///< the same, 2 px
  double bad2_all = 0.0;         ///< share of known pixels unmatched or off by more than 2 px
  double median_error_px = 0.0;  ///< median |estimate - truth| over matched pixels
  double density() const { return known ? static_cast<double>(matched) / static_cast<double>(known) : 0.0; }
};

/// `estimate_px`, `truth_px`: CV_32F disparities in pixels of the same size; a value that is not
/// finite or not positive is unknown (no estimate, no truth). kestrel::Error on other inputs.
DisparityScore score_disparity(const cv::Mat& estimate_px, const cv::Mat& truth_px);

/// A matcher's CV_16S disparity (1/16 px, negative: none) in pixels, none as NaN.
cv::Mat disparity_in_pixels(const cv::Mat& disparity16);

/// Ground truth from a file: a PFM of float disparities (Middlebury 2014; infinite or NaN:
/// unknown) or an 8-bit PNG of whole disparities (Middlebury 2006; 0: unknown), in pixels, CV_32F,
/// unknown as NaN. kestrel::Error if the file cannot be read as one.
cv::Mat read_disparity_truth(const std::filesystem::path& file);

}  // namespace kestrel::stereo
