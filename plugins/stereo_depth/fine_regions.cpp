#include "fine_regions.hpp"

#include <opencv2/imgproc.hpp>

namespace kestrel::stereo {

namespace {

// Pixels of SGBM's paths matched before a region's box, so that they have settled at its edges
// (without, pixels of a wall beside an object took the object's disparity).
constexpr int kRunInPx = 16;

}  // namespace

std::vector<cv::Rect> fine_regions(const cv::Mat& coarse_mask, int factor, cv::Size full, int margin_px) {
  CV_Assert(coarse_mask.type() == CV_8U && factor >= 1 && margin_px >= 0);
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(coarse_mask, labels, stats, centroids, 8, CV_32S);
  const cv::Rect image(cv::Point(0, 0), full);
  std::vector<cv::Rect> boxes;
  for (int i = 1; i < n; ++i) {
    const int x = stats.at<int>(i, cv::CC_STAT_LEFT), y = stats.at<int>(i, cv::CC_STAT_TOP);
    const int w = stats.at<int>(i, cv::CC_STAT_WIDTH), h = stats.at<int>(i, cv::CC_STAT_HEIGHT);
    boxes.push_back(cv::Rect(x * factor - margin_px, y * factor - margin_px, w * factor + 2 * margin_px,
                             h * factor + 2 * margin_px) &
                    image);
  }
  // Merge until no two overlap (few boxes a frame: the quadratic loop is cheap).
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t i = 0; i < boxes.size() && !changed; ++i)
      for (std::size_t j = i + 1; j < boxes.size() && !changed; ++j)
        if ((boxes[i] & boxes[j]).area() > 0) {
          boxes[i] |= boxes[j];
          boxes.erase(boxes.begin() + static_cast<std::ptrdiff_t>(j));
          changed = true;
        }
  }
  return boxes;
}

cv::Mat match_region(const GreyPair& pair, const cv::Rect& box, const MatcherOptions& options) {
  // SGBM's paths come from the left, from the right within the row and from the rows above: they
  // start a run-in before the box. On the left the search also reaches its disparities further;
  // below, the block and the median reach a little.
  const int below = options.block_size / 2 + 2;
  const cv::Rect image(0, 0, pair.left.cols, pair.left.rows);
  const cv::Rect crop =
      cv::Rect(cv::Point(box.x - options.min_disparity - options.num_disparities - kRunInPx, box.y - kRunInPx),
               cv::Point(box.br().x + kRunInPx, box.br().y + below)) &
      image;
  cv::Mat disparity;
  make_matcher(options)->compute(pair.left(crop), pair.right(crop), disparity);
  return disparity(box - crop.tl()).clone();
}

}  // namespace kestrel::stereo
