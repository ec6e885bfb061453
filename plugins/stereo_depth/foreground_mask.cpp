#include "foreground_mask.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <vector>

namespace kestrel::stereo {

namespace {

template <class Op>
cv::Mat vertical_running(const cv::Mat& image, int radius, float identity, Op op) {
  CV_Assert(image.type() == CV_32F && radius >= 0);
  const int rows = image.rows, cols = image.cols, k = 2 * radius + 1;
  if (radius == 0 || rows == 0) return image.clone();
  // Padded with the identity by `radius` rows above and enough below for whole blocks of k rows.
  const int padded_rows = (rows + 2 * radius + k - 1) / k * k;
  cv::Mat padded(padded_rows, cols, CV_32F, cv::Scalar(identity));
  image.copyTo(padded.rowRange(radius, radius + rows));
  cv::Mat prefix(padded_rows, cols, CV_32F), suffix(padded_rows, cols, CV_32F);
  for (int start = 0; start < padded_rows; start += k) {
    padded.row(start).copyTo(prefix.row(start));
    for (int v = start + 1; v < start + k; ++v) {
      const float* in = padded.ptr<float>(v);
      const float* above = prefix.ptr<float>(v - 1);
      float* out = prefix.ptr<float>(v);
      for (int u = 0; u < cols; ++u) out[u] = op(above[u], in[u]);
    }
    padded.row(start + k - 1).copyTo(suffix.row(start + k - 1));
    for (int v = start + k - 2; v >= start; --v) {
      const float* in = padded.ptr<float>(v);
      const float* below = suffix.ptr<float>(v + 1);
      float* out = suffix.ptr<float>(v);
      for (int u = 0; u < cols; ++u) out[u] = op(below[u], in[u]);
    }
  }
  // Row v of the image is padded row v + radius, the centre of padded rows [v, v + k - 1].
  cv::Mat result(rows, cols, CV_32F);
  for (int v = 0; v < rows; ++v) {
    const float* s = suffix.ptr<float>(v);
    const float* p = prefix.ptr<float>(v + k - 1);
    float* out = result.ptr<float>(v);
    for (int u = 0; u < cols; ++u) out[u] = op(s[u], p[u]);
  }
  return result;
}

}  // namespace

cv::Mat vertical_erode(const cv::Mat& image, int radius) {
  return vertical_running(image, radius, std::numeric_limits<float>::infinity(),
                          [](float a, float b) { return std::min(a, b); });
}

cv::Mat vertical_dilate(const cv::Mat& image, int radius) {
  return vertical_running(image, radius, -std::numeric_limits<float>::infinity(),
                          [](float a, float b) { return std::max(a, b); });
}

void fill_short_holes_down(cv::Mat& disparity, int max_run) {
  CV_Assert(disparity.type() == CV_32F);
  for (int u = 0; u < disparity.cols; ++u) {
    int last_valid = -1;
    for (int v = 0; v < disparity.rows; ++v) {
      const float d = disparity.at<float>(v, u);
      if (d <= 0.0f) continue;
      const int run = v - last_valid - 1;
      if (last_valid >= 0 && run > 0 && run <= max_run) {
        const float fill = std::min(d, disparity.at<float>(last_valid, u));
        for (int w = last_valid + 1; w < v; ++w) disparity.at<float>(w, u) = fill;
      }
      last_valid = v;
    }
  }
}

namespace {

// The background's resolution: columns of the map the openings run on, at most.
constexpr int kBackgroundWidth = 320;

}  // namespace

DisparityBackground::Openings::Openings(const cv::Mat& disparity, double max_disparity, double pixels_per_disparity_)
    : pixels_per_disparity(pixels_per_disparity_) {
  const int largest = std::min(radius_for(max_disparity), disparity.rows);
  for (int r = 1;; r *= 2) {
    radii.push_back(std::min(r, largest));
    images.push_back(vertical_dilate(vertical_erode(disparity, radii.back()), radii.back()));
    if (r >= largest) break;
  }
}

int DisparityBackground::Openings::radius_for(double d) const {
  return static_cast<int>(std::floor(pixels_per_disparity * d / 2.0)) + 1;
}

float DisparityBackground::Openings::at(int row, int col, float d) const {
  const int need = radius_for(d);
  std::size_t scale = 0;
  while (scale + 1 < radii.size() && radii[scale] < need) ++scale;
  return images[scale].at<float>(row, col);
}

cv::Mat disparity_unmatched_far(const cv::Mat& disparity16) {
  CV_Assert(disparity16.type() == CV_16S);
  cv::Mat disparity;
  disparity16.convertTo(disparity, CV_32F, 1.0 / 16.0);
  disparity.setTo(0.0f, disparity16 <= 0);  // no match (sky): as far as can be
  return disparity;
}

DisparityBackground::DisparityBackground(const cv::Mat& disparity, const msg::StereoCalibration& c,
                                         const ForegroundOptions& o)
    : first_(std::clamp(o.unseen_left_columns, 0, disparity.cols)), rows_(disparity.rows), cols_(disparity.cols) {
  CV_Assert(disparity.type() == CV_32F);
  if (first_ == cols_) return;
  double max_disparity = 0.0;
  cv::minMaxLoc(disparity, nullptr, &max_disparity);
  // The columns on the left that the right camera does not see hold no match at all: they are
  // outside the picture, not a view of the sky.
  const cv::Mat seen = disparity.colRange(first_, disparity.cols);
  // What the openings see: the map subsampled to at most kBackgroundWidth columns (the
  // background needs no finer detail, and the openings cost a quarter at half resolution), short
  // holes filled down the columns, then along the rows.
  k_ = (seen.cols + kBackgroundWidth - 1) / kBackgroundWidth;
  cv::Mat background;
  cv::resize(seen, background, cv::Size((seen.cols + k_ - 1) / k_, (seen.rows + k_ - 1) / k_), 0, 0, cv::INTER_NEAREST);
  if (o.max_hole_px > 0) {
    const int hole = std::max(1, o.max_hole_px / k_);
    fill_short_holes_down(background, hole);
    cv::Mat across = background.t();
    fill_short_holes_down(across, hole);
    background = across.t();
  }
  // Rows: an object H tall at disparity d spans H * fy / Z = H * d * fy / (fx * b) rows; columns:
  // W * d / b; k times fewer in the subsampled map. Columns are opened as the rows of the
  // transposed map.
  down_.emplace(background, max_disparity, o.max_height_m * c.fy / (c.fx * c.baseline_m) / k_);
  across_.emplace(background.t(), max_disparity, o.max_width_m / c.baseline_m / k_);
}

float DisparityBackground::behind(int row, int col, float d) const {
  const int u = (col - first_) / k_, v = row / k_;
  return std::max(down_->at(v, u, d), across_->at(u, v, d));
}

double standing_out_threshold(double d, double focal_baseline, const ForegroundOptions& o) {
  // Standing gap_m in front of a background at depth Z + gap: d - fb / (fb / d + gap).
  return std::max(o.gap_m * d * d / (focal_baseline + o.gap_m * d), o.min_step_px);
}

cv::Mat foreground_mask(const cv::Mat& disparity16, const msg::StereoCalibration& c, const ForegroundOptions& o) {
  const cv::Mat disparity = disparity_unmatched_far(disparity16);
  return foreground_mask(disparity, DisparityBackground(disparity, c, o), c, o);
}

cv::Mat foreground_mask(const cv::Mat& disparity, const DisparityBackground& background,
                        const msg::StereoCalibration& c, const ForegroundOptions& o) {
  CV_Assert(disparity.type() == CV_32F);
  const double fb = c.fx * c.baseline_m;
  cv::Mat mask(disparity.size(), CV_8U, cv::Scalar(0));
  for (int v = 0; v < disparity.rows; ++v) {
    const float* d = disparity.ptr<float>(v);
    std::uint8_t* m = mask.ptr<std::uint8_t>(v);
    for (int u = 0; u < disparity.cols; ++u) {
      if (d[u] <= 0.0f || !background.sees(u)) continue;
      // In front of what is above and below it, and of what is left and right of it.
      if (d[u] - background.behind(v, u, d[u]) >= standing_out_threshold(d[u], fb, o)) m[u] = 255;
    }
  }
  open_thin_parts(mask, o.min_thickness_px);
  return mask;
}

void open_thin_parts(cv::Mat& mask, int min_thickness_px) {
  if (min_thickness_px > 1)
    cv::morphologyEx(mask, mask, cv::MORPH_OPEN,
                     cv::getStructuringElement(cv::MORPH_RECT, {min_thickness_px, min_thickness_px}));
}

}  // namespace kestrel::stereo

namespace kestrel::stereo {

ForegroundOptions options_for_downscale(ForegroundOptions options, int factor, const MatcherOptions& matcher) {
  const auto shrink = [&](int px) { return px > 0 ? std::max(1, (px + factor / 2) / factor) : 0; };
  options.min_thickness_px = shrink(options.min_thickness_px);
  options.max_hole_px = shrink(options.max_hole_px);
  options.unseen_left_columns = std::max(0, matcher.min_disparity + matcher.num_disparities);
  return options;
}

}  // namespace kestrel::stereo
