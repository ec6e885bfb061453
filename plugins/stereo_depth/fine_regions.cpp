#include "fine_regions.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace kestrel::stereo {

namespace {

// Pixels of SGBM's paths matched before a region's box, so that they have settled at its edges.
constexpr int kRunInPx = 16;

// Disparities [lo, hi] in full-resolution pixels, as OpenCV searches them: from min_disparity,
// num_disparities of them, a multiple of 16.
FineRegion with_disparities(cv::Rect box, double lo, double hi) {
  FineRegion r;
  r.box = box;
  r.min_disparity = std::max(0, static_cast<int>(std::floor(lo)));
  const int span = static_cast<int>(std::ceil(hi)) - r.min_disparity + 1;
  r.num_disparities = std::max(16, (span + 15) / 16 * 16);
  return r;
}

bool overlap(const FineRegion& a, const FineRegion& b) { return (a.box & b.box).area() > 0; }

FineRegion merged(const FineRegion& a, const FineRegion& b) {
  const int hi = std::max(a.min_disparity + a.num_disparities, b.min_disparity + b.num_disparities) - 1;
  return with_disparities(a.box | b.box, std::min(a.min_disparity, b.min_disparity), hi);
}

}  // namespace

std::vector<FineRegion> fine_regions(const cv::Mat& coarse_mask, const cv::Mat& coarse_disparity, int factor,
                                     cv::Size full, const FineRegionOptions& o) {
  CV_Assert(coarse_mask.type() == CV_8U && coarse_disparity.type() == CV_32F &&
            coarse_mask.size() == coarse_disparity.size() && factor >= 1);
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(coarse_mask, labels, stats, centroids, 8, CV_32S);
  const cv::Rect image(cv::Point(0, 0), full), coarse_image(cv::Point(0, 0), coarse_mask.size());
  const int grow = (o.margin_px + factor - 1) / factor;
  std::vector<FineRegion> regions;
  for (int i = 1; i < n; ++i) {
    const cv::Rect coarse(stats.at<int>(i, cv::CC_STAT_LEFT), stats.at<int>(i, cv::CC_STAT_TOP),
                          stats.at<int>(i, cv::CC_STAT_WIDTH), stats.at<int>(i, cv::CC_STAT_HEIGHT));
    const cv::Rect box = cv::Rect(coarse.x * factor - o.margin_px, coarse.y * factor - o.margin_px,
                                  coarse.width * factor + 2 * o.margin_px, coarse.height * factor + 2 * o.margin_px) &
                         image;
    // Every disparity the box's coarse pixels hold, the background's as well as the object's: a
    // pixel beside the object (one the right camera does not see, say) must find its own match,
    // or it takes the object's and fattens it.
    const cv::Rect around =
        cv::Rect(coarse.x - grow, coarse.y - grow, coarse.width + 2 * grow, coarse.height + 2 * grow) & coarse_image;
    float lo = INFINITY, hi = 0.0f;
    for (int v = around.y; v < around.br().y; ++v) {
      const float* d = coarse_disparity.ptr<float>(v);
      for (int u = around.x; u < around.br().x; ++u)
        if (d[u] > 0.0f) {
          lo = std::min(lo, d[u]);
          hi = std::max(hi, d[u]);
        }
    }
    if (hi <= 0.0f) continue;
    // A coarse disparity d holds full-resolution disparities within a coarse pixel of d * factor.
    regions.push_back(with_disparities(box, (lo - 1.0) * factor - o.disparity_margin_px,
                                       (hi + 1.0) * factor + o.disparity_margin_px));
  }
  // Merge until no two overlap (few regions a frame: the quadratic loop is cheap).
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t i = 0; i < regions.size() && !changed; ++i)
      for (std::size_t j = i + 1; j < regions.size() && !changed; ++j)
        if (overlap(regions[i], regions[j])) {
          regions[i] = merged(regions[i], regions[j]);
          regions.erase(regions.begin() + static_cast<std::ptrdiff_t>(j));
          changed = true;
        }
  }
  return regions;
}

cv::Mat match_region(const GreyPair& pair, const FineRegion& region, MatcherOptions options) {
  options.min_disparity = region.min_disparity;
  options.num_disparities = region.num_disparities;
  // SGBM's paths come from the left and from the rows above: they need a run-in before the box,
  // or the pixels on its left and top edges take a path that has seen nothing yet (pixels of a
  // wall beside an object were given the object's disparity without). On the left, the search
  // also reaches its disparities further; below and on the right, the block and the median.
  const int reach = options.block_size / 2 + 2;
  const cv::Rect image(0, 0, pair.left.cols, pair.left.rows);
  const cv::Rect crop = cv::Rect(cv::Point(region.box.x - region.min_disparity - region.num_disparities - kRunInPx,
                                           region.box.y - kRunInPx),
                                 cv::Point(region.box.br().x + reach, region.box.br().y + reach)) &
                        image;
  const auto matcher = make_matcher(options);
  cv::Mat disparity;
  matcher->compute(pair.left(crop), pair.right(crop), disparity);
  return disparity(region.box - crop.tl()).clone();
}

}  // namespace kestrel::stereo
