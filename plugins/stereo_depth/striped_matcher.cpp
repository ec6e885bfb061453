#include "striped_matcher.hpp"

#include <opencv2/core/utility.hpp>

#include "kestrel/error.hpp"

namespace kestrel::stereo {

StripedMatcher::StripedMatcher(const MatcherOptions& options, int strips, int overlap_rows)
    : options_(options), overlap_rows_(overlap_rows) {
  if (strips < 1) throw Error("strips must be at least 1, not " + std::to_string(strips));
  if (overlap_rows < 0) throw Error("strip overlap must not be negative");
  if (strips == 1) {
    matchers_.push_back(make_matcher(options));
    return;
  }
  if (!is_five_path_sgbm(options)) throw Error("strips > 1 needs algorithm sgbm in mode sgbm");
  MatcherOptions strip = options;
  strip.speckle_window_size = 0;  // on the merged map instead
  for (int i = 0; i < strips; ++i) matchers_.push_back(make_matcher(strip));
}

cv::Mat StripedMatcher::compute(const cv::Mat& left, const cv::Mat& right) {
  if (matchers_.size() == 1) return compute_disparity(*matchers_.front(), left, right);
  // Checks and the conversion to grey once, for every strip.
  const GreyPair grey = grey_pair(left, right);
  const cv::Mat& l = grey.left;
  const cv::Mat& r = grey.right;
  // Strips of equal work: every strip but the first also matches the overlap above it, so the
  // first keeps `overlap_rows_` more rows than each of the others.
  const int rows = l.rows;
  int n = strips();
  while (n > 1 && (rows + (n - 1) * overlap_rows_) / n - overlap_rows_ < 1) --n;
  const int first_rows = (rows + (n - 1) * overlap_rows_) / n;
  std::vector<int> bounds{0};
  for (int i = 0; i < n; ++i)
    bounds.push_back(i + 1 == n ? rows : bounds.back() + first_rows - (i == 0 ? 0 : overlap_rows_));
  // Below its last row a strip needs the rows its block, its pixel costs and the 3x3 median reach.
  const int below = options_.block_size / 2 + 2;
  cv::Mat disparity(l.size(), CV_16S);
  cv::parallel_for_(
      cv::Range(0, n),
      [&](const cv::Range& range) {
        for (int i = range.start; i < range.end; ++i) {
          const int first = bounds[static_cast<std::size_t>(i)], last = bounds[static_cast<std::size_t>(i) + 1];
          const int top = std::max(0, first - (i == 0 ? 0 : overlap_rows_));
          const int bottom = std::min(rows, last + below);
          cv::Mat strip;
          matchers_[static_cast<std::size_t>(i)]->compute(l.rowRange(top, bottom), r.rowRange(top, bottom), strip);
          strip.rowRange(first - top, last - top).copyTo(disparity.rowRange(first, last));
        }
      },
      n);
  if (options_.speckle_window_size > 0)
    cv::filterSpeckles(disparity, (options_.min_disparity - 1) * cv::StereoMatcher::DISP_SCALE,
                       options_.speckle_window_size, cv::StereoMatcher::DISP_SCALE * options_.speckle_range);
  return disparity;
}

}  // namespace kestrel::stereo
