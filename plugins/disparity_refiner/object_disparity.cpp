#include "object_disparity.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>

namespace kestrel::refine {

namespace {

double median(std::vector<double> v) {
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

// Bilinear sample of a CV_32F image at (x, y); the caller keeps (x, y) inside.
float sample(const cv::Mat& image, double x, int y) {
  const int x0 = static_cast<int>(std::floor(x));
  const double w = x - x0;
  const float* row = image.ptr<float>(y);
  return static_cast<float>((1.0 - w) * row[x0] + w * row[x0 + 1]);
}

struct Pixel {
  int u, v;
  float left;
};

}  // namespace

std::optional<ObjectMask> object_mask(const pcl::PointCloud<pcl::PointXYZ>& cloud, const msg::StereoCalibration& c,
                                      const Eigen::Vector3d& centre, const Eigen::Vector3d& half_extent,
                                      double margin_m, int erode_px, int min_pixels, int pixels_per_point) {
  const int side = std::max(1, pixels_per_point);
  // The square's first pixel: its centre lies where the point projects.
  const double to_corner = 0.5 * (side - 1);
  const Eigen::Vector3d reach = half_extent.array() + margin_m;
  struct Hit {
    int u, v;
    float d;
  };
  std::vector<Hit> hits;
  int u_min = c.width, v_min = c.height, u_max = -1, v_max = -1;
  for (const auto& point : cloud) {
    const Eigen::Vector3f p = point.getVector3fMap();
    if (!(p.z() > 0.0f) || ((p.cast<double>() - centre).cwiseAbs().array() > reach.array()).any()) continue;
    const int u = static_cast<int>(std::lround(c.fx * p.x() / p.z() + c.cx - to_corner));
    const int v = static_cast<int>(std::lround(c.fy * p.y() / p.z() + c.cy - to_corner));
    const float d = static_cast<float>(c.fx * c.baseline_m / p.z());
    for (int dv = 0; dv < side; ++dv)
      for (int du = 0; du < side; ++du) {
        if (u + du < 0 || v + dv < 0 || u + du >= c.width || v + dv >= c.height) continue;
        hits.push_back({u + du, v + dv, d});
        u_min = std::min(u_min, u + du), u_max = std::max(u_max, u + du);
        v_min = std::min(v_min, v + dv), v_max = std::max(v_max, v + dv);
      }
  }
  if (static_cast<int>(hits.size()) < min_pixels) return std::nullopt;
  ObjectMask mask;
  mask.roi = cv::Rect(u_min, v_min, u_max - u_min + 1, v_max - v_min + 1);
  mask.pixels = cv::Mat::zeros(mask.roi.size(), CV_8U);
  mask.disparity = cv::Mat::zeros(mask.roi.size(), CV_32F);
  for (const auto& h : hits) {
    mask.pixels.at<std::uint8_t>(h.v - v_min, h.u - u_min) = 255;
    mask.disparity.at<float>(h.v - v_min, h.u - u_min) = h.d;
  }
  // Close the holes where SGBM gave no disparity inside the drone, then peel the silhouette.
  const cv::Mat kernel = cv::getStructuringElement(cv::MORPH_RECT, {3, 3});
  cv::morphologyEx(mask.pixels, mask.pixels, cv::MORPH_CLOSE, kernel);
  if (erode_px > 0) cv::erode(mask.pixels, mask.pixels, kernel, {-1, -1}, erode_px, cv::BORDER_CONSTANT, 0);
  mask.count = cv::countNonZero(mask.pixels);
  if (mask.count < min_pixels) return std::nullopt;
  std::vector<double> own;
  for (int y = 0; y < mask.pixels.rows; ++y)
    for (int x = 0; x < mask.pixels.cols; ++x)
      if (mask.pixels.at<std::uint8_t>(y, x) && mask.disparity.at<float>(y, x) > 0)
        own.push_back(mask.disparity.at<float>(y, x));
  if (own.empty()) return std::nullopt;
  mask.sgbm_disparity = median(own);
  return mask;
}

int drop_background(const cv::Mat& left, const cv::Mat& right, ObjectMask& mask, const BackgroundOptions& o) {
  CV_Assert(left.type() == CV_32F && right.type() == CV_32F && left.size() == right.size());
  const int r = o.radius_px;
  const double object = mask.sgbm_disparity;
  const double farthest_behind = object - o.gap_px;
  if (farthest_behind < 0) return 0;  // nothing can be told apart from the object
  // The pixels judged: the whole window, at every candidate, inside both images. (Bilinear
  // samples read one pixel to the right of where they fall.)
  std::vector<cv::Point> judged;
  cv::Rect reach;
  for (int y = 0; y < mask.pixels.rows; ++y)
    for (int x = 0; x < mask.pixels.cols; ++x) {
      if (!mask.pixels.at<std::uint8_t>(y, x)) continue;
      const int u = mask.roi.x + x, v = mask.roi.y + y;
      if (v - r < 0 || v + r >= left.rows || u + r + 1 >= left.cols || u - r - object - 1 < 0) continue;
      judged.emplace_back(x, y);
      reach |= cv::Rect(u - r, v - r, 2 * r + 1, 2 * r + 1);
    }
  if (judged.empty()) return 0;
  // |left - right shifted by d| over every window at once: neighbouring windows overlap, so each
  // difference is sampled once per candidate instead of once per window that holds it. The sums
  // below add the same terms in the same order as a window at a time would.
  cv::Mat difference(reach.size(), CV_32F);
  const auto differences_at = [&](double d) {
    for (int y = 0; y < reach.height; ++y) {
      const int v = reach.y + y;
      const float* l = left.ptr<float>(v);
      float* out = difference.ptr<float>(y);
      for (int x = 0; x < reach.width; ++x) {
        const int u = reach.x + x;
        out[x] = std::abs(l[u] - sample(right, u - d, v));
      }
    }
  };
  // A window's cost, given up once it reaches `bound` (it can no longer be the least).
  const auto window_cost = [&](const cv::Point& p, double bound) {
    const int x0 = mask.roi.x + p.x - reach.x, y0 = mask.roi.y + p.y - reach.y;
    double cost = 0.0;
    for (int j = -r; j <= r && cost < bound; ++j) {
      const float* row = difference.ptr<float>(y0 + j);
      for (int i = -r; i <= r; ++i) cost += row[x0 + i];
    }
    return cost;
  };
  differences_at(object);
  std::vector<double> own(judged.size());
  for (std::size_t k = 0; k < judged.size(); ++k)
    own[k] = window_cost(judged[k], std::numeric_limits<double>::infinity());
  std::vector<double> best_behind(judged.size(), std::numeric_limits<double>::infinity());
  // Half-pixel steps: far backgrounds have fractional disparities.
  for (double d = 0.0; d <= farthest_behind; d += 0.5) {
    differences_at(d);
    for (std::size_t k = 0; k < judged.size(); ++k)
      best_behind[k] = std::min(best_behind[k], window_cost(judged[k], best_behind[k]));
  }
  int dropped = 0;
  for (std::size_t k = 0; k < judged.size(); ++k)
    if (best_behind[k] < o.ratio * own[k]) {
      mask.pixels.at<std::uint8_t>(judged[k]) = 0;
      ++dropped;
    }
  mask.count -= dropped;
  return dropped;
}

std::optional<double> robust_mean_disparity(const ObjectMask& mask) {
  std::vector<double> own;
  for (int y = 0; y < mask.pixels.rows; ++y)
    for (int x = 0; x < mask.pixels.cols; ++x)
      if (mask.pixels.at<std::uint8_t>(y, x) && mask.disparity.at<float>(y, x) > 0)
        own.push_back(mask.disparity.at<float>(y, x));
  if (own.empty()) return std::nullopt;
  const double m = median(own);
  std::vector<double> deviation;
  for (const double d : own) deviation.push_back(std::abs(d - m));
  const double limit = 3.0 * 1.4826 * median(deviation) + 1e-9;
  double sum = 0.0;
  int n = 0;
  for (const double d : own)
    if (std::abs(d - m) <= limit) sum += d, ++n;
  return sum / n;
}

std::optional<double> match_disparity(const cv::Mat& left, const cv::Mat& right, const ObjectMask& mask,
                                      const MatchOptions& options) {
  CV_Assert(left.type() == CV_32F && right.type() == CV_32F && left.size() == right.size());
  std::vector<Pixel> pixels;
  double mean_left = 0.0;
  for (int y = 0; y < mask.pixels.rows; ++y)
    for (int x = 0; x < mask.pixels.cols; ++x)
      if (mask.pixels.at<std::uint8_t>(y, x)) {
        const int u = mask.roi.x + x, v = mask.roi.y + y;
        pixels.push_back({u, v, left.at<float>(v, u)});
        mean_left += pixels.back().left;
      }
  if (pixels.empty()) return std::nullopt;
  mean_left /= static_cast<double>(pixels.size());
  double var_left = 0.0;
  for (const auto& p : pixels) var_left += (p.left - mean_left) * (p.left - mean_left);
  if (var_left < 1e-6 * static_cast<double>(pixels.size())) return std::nullopt;  // no texture to match

  // Whole pixels first, by ZNCC; a disparity whose window leaves the image is not a candidate.
  const auto inside = [&](double d) {
    for (const auto& p : pixels)
      if (p.u - d < 0.0 || p.u - d > right.cols - 2) return false;
    return true;
  };
  const auto zncc = [&](int d) {
    double mean_right = 0.0;
    for (const auto& p : pixels) mean_right += right.at<float>(p.v, p.u - d);
    mean_right /= static_cast<double>(pixels.size());
    double cross = 0.0, var_right = 0.0;
    for (const auto& p : pixels) {
      const double r = right.at<float>(p.v, p.u - d) - mean_right;
      cross += (p.left - mean_left) * r;
      var_right += r * r;
    }
    return var_right > 0.0 ? cross / std::sqrt(var_left * var_right) : -1.0;
  };
  const int lo = static_cast<int>(std::floor(mask.sgbm_disparity - options.search_px));
  const int hi = static_cast<int>(std::ceil(mask.sgbm_disparity + options.search_px));
  int best = -1;
  double best_score = -2.0;
  for (int d = std::max(lo, 1); d <= hi; ++d)
    if (inside(d + 1.0) && inside(d - 1.0))
      if (const double s = zncc(d); s > best_score) best_score = s, best = d;
  if (best < 0) return std::nullopt;
  // A parabola through the scores either side: the start for Gauss-Newton.
  const double sm = zncc(best - 1), s0 = best_score, sp = zncc(best + 1);
  const double curvature = sm - 2.0 * s0 + sp;
  double d = best + (curvature < 0.0 ? 0.5 * (sm - sp) / curvature : 0.0);

  // Gauss-Newton on sum((R(u - d) - mean R) - (L(u) - mean L))^2, R interpolated bilinearly: no
  // pull towards whole pixels, which a parabola on correlation scores has.
  for (int it = 0; it < options.iterations; ++it) {
    if (!inside(d + 1.0) || !inside(d - 1.0)) return std::nullopt;
    double mean_right = 0.0;
    std::vector<double> r(pixels.size()), g(pixels.size());
    for (std::size_t i = 0; i < pixels.size(); ++i) {
      const double x = pixels[i].u - d;
      r[i] = sample(right, x, pixels[i].v);
      g[i] = sample(right, x + 0.5, pixels[i].v) - sample(right, x - 0.5, pixels[i].v);  // dR/dx
      mean_right += r[i];
    }
    mean_right /= static_cast<double>(pixels.size());
    double num = 0.0, den = 0.0;
    for (std::size_t i = 0; i < pixels.size(); ++i) {
      const double e = (r[i] - mean_right) - (pixels[i].left - mean_left);
      // d/dd R(u - d) = -R'(u - d)
      num += -g[i] * e;
      den += g[i] * g[i];
    }
    if (den <= 0.0) break;
    const double step = std::clamp(-num / den, -0.5, 0.5);
    d += step;
    if (std::abs(step) < 1e-4) break;
  }
  if (std::abs(d - best) > 1.0) return std::nullopt;  // it wandered: not a match
  return d;
}

Eigen::Vector3d place(const msg::StereoCalibration& c, const ObjectMask& mask, double disparity) {
  const cv::Moments m = cv::moments(mask.pixels, true);
  const double u = mask.roi.x + m.m10 / m.m00, v = mask.roi.y + m.m01 / m.m00;
  const double z = c.fx * c.baseline_m / disparity;
  return {(u - c.cx) * z / c.fx, (v - c.cy) * z / c.fy, z};
}

Eigen::Vector3d centre_behind(const Eigen::Vector3d& surface, double metres) {
  return surface + metres * surface.normalized();
}

}  // namespace kestrel::refine
