#pragma once
// SGBM on two cores: the pair matched as horizontal strips in parallel.
//
// OpenCV's 5-path SGBM (mode `sgbm`, the paper's matcher) runs on one core, and at 640x480 with 80
// disparities it takes longer than a 30 FPS frame. Its paths all come from the left or from the
// rows above, so a row's disparity depends only on the rows above it (and on the few rows below
// that its block and the 3x3 median reach). A strip is therefore matched with its own rows plus
// `overlap_rows` rows above, whose results are dropped: the first strip is exactly what matching
// the whole image gives, and the others differ only where a path reaching more than
// `overlap_rows` rows up would have changed a pixel's best disparity. The speckle filter, which
// joins regions across the whole image, runs once on the merged map, as OpenCV runs it.
#include <opencv2/calib3d.hpp>
#include <vector>

#include "stereo_matching.hpp"

namespace kestrel::stereo {

class StripedMatcher {
 public:
  /// `strips` == 1 is OpenCV's matcher unchanged. More strips need algorithm `sgbm` in mode `sgbm`
  /// (the other modes aggregate from below too, or are parallel already); throws kestrel::Error.
  StripedMatcher(const MatcherOptions& options, int strips, int overlap_rows);

  /// The same contract as compute_disparity: 8-bit grey or BGR pair in, CV_16S disparity out.
  cv::Mat compute(const cv::Mat& left, const cv::Mat& right);

  int strips() const { return static_cast<int>(matchers_.size()); }

 private:
  MatcherOptions options_;
  int overlap_rows_;
  std::vector<cv::Ptr<cv::StereoMatcher>> matchers_;  // one per strip: a matcher keeps its buffers
};

}  // namespace kestrel::stereo
