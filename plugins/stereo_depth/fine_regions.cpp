#include "fine_regions.hpp"

#include <algorithm>
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

RegionMatch match_region_crop(const GreyPair& pair, const cv::Rect& box, const MatcherOptions& options) {
  // SGBM's paths come from the left, from the right within the row and from the rows above: they
  // start a run-in before the box. On the left the search also reaches its disparities further;
  // below, the block and the median reach a little.
  const int below = options.block_size / 2 + 2;
  const int search = options.min_disparity + options.num_disparities;
  const cv::Rect image(0, 0, pair.left.cols, pair.left.rows);
  const cv::Rect crop = cv::Rect(cv::Point(box.x - search - kRunInPx, box.y - kRunInPx),
                                 cv::Point(box.br().x + kRunInPx, box.br().y + below)) &
                        image;
  RegionMatch match;
  make_matcher(options)->compute(pair.left(crop), pair.right(crop), match.disparity16);
  match.box = box - crop.tl();
  return match;
}

cv::Mat region_foreground(const cv::Mat& crop, const cv::Rect& box, cv::Point box_origin, int f,
                          const DisparityBackground& coarse, const DisparityBackground* own, double fb,
                          const ForegroundOptions& options) {
  CV_Assert(crop.type() == CV_32F && f >= 1);
  cv::Mat mask(box.size(), CV_8U, cv::Scalar(0));
  for (int v = 0; v < box.height; ++v) {
    const int row = std::min((box_origin.y + v) / f, coarse.rows() - 1);
    const float* d = crop.ptr<float>(box.y + v) + box.x;
    std::uint8_t* m = mask.ptr<std::uint8_t>(v);
    for (int u = 0; u < box.width; ++u) {
      const int col = std::min((box_origin.x + u) / f, coarse.cols() - 1);
      if (d[u] <= 0.0f || !coarse.sees(col)) continue;
      float behind = static_cast<float>(f) * coarse.behind(row, col, d[u] / static_cast<float>(f));
      if (own != nullptr && own->sees(box.x + u)) behind = std::max(behind, own->behind(box.y + v, box.x + u, d[u]));
      if (d[u] - behind >= standing_out_threshold(d[u], fb, options)) m[u] = 255;
    }
  }
  open_thin_parts(mask, options.min_thickness_px);
  return mask;
}

cv::Mat match_region(const GreyPair& pair, const cv::Rect& box, const MatcherOptions& options) {
  const RegionMatch match = match_region_crop(pair, box, options);
  return match.disparity16(match.box).clone();
}

}  // namespace kestrel::stereo
