#include "stereo_matching.hpp"

#include <opencv2/imgproc.hpp>

#include "kestrel/error.hpp"

namespace kestrel::stereo {

cv::Ptr<cv::StereoMatcher> make_matcher(const MatcherOptions& o) {
  if (o.num_disparities <= 0 || o.num_disparities % 16 != 0)
    throw Error("num_disparities must be a positive multiple of 16, not " + std::to_string(o.num_disparities));
  if (o.block_size % 2 == 0) throw Error("block_size must be odd, not " + std::to_string(o.block_size));
  if (o.algorithm == MatcherOptions::Algorithm::bm) {
    if (o.block_size < 5) throw Error("StereoBM needs block_size >= 5");
    auto bm = cv::StereoBM::create(o.num_disparities, o.block_size);
    bm->setMinDisparity(o.min_disparity);
    bm->setUniquenessRatio(o.uniqueness_ratio);
    bm->setSpeckleWindowSize(o.speckle_window_size);
    bm->setSpeckleRange(o.speckle_range);
    bm->setDisp12MaxDiff(o.disp12_max_diff);
    bm->setPreFilterCap(std::min(o.pre_filter_cap, 63));
    bm->setTextureThreshold(o.texture_threshold);
    return bm;
  }
  const int area = o.block_size * o.block_size;
  const int p1 = o.p1 > 0 ? o.p1 : 8 * area;
  const int p2 = o.p2 > 0 ? o.p2 : 32 * area;
  if (p2 <= p1) throw Error("SGBM needs p2 > p1");
  int mode = cv::StereoSGBM::MODE_SGBM;
  switch (o.mode) {
    case MatcherOptions::Mode::sgbm:
      break;
    case MatcherOptions::Mode::hh:
      mode = cv::StereoSGBM::MODE_HH;
      break;
    case MatcherOptions::Mode::sgbm_3way:
      mode = cv::StereoSGBM::MODE_SGBM_3WAY;
      break;
    case MatcherOptions::Mode::hh4:
      mode = cv::StereoSGBM::MODE_HH4;
      break;
  }
  return cv::StereoSGBM::create(o.min_disparity, o.num_disparities, o.block_size, p1, p2, o.disp12_max_diff,
                                o.pre_filter_cap, o.uniqueness_ratio, o.speckle_window_size, o.speckle_range, mode);
}

GreyPair grey_pair(const cv::Mat& left, const cv::Mat& right) {
  if (left.empty() || right.empty()) throw Error("empty stereo image");
  if (left.size() != right.size() || left.type() != right.type())
    throw Error("left and right images differ in size or type");
  if (left.depth() != CV_8U || (left.channels() != 1 && left.channels() != 3))
    throw Error("stereo images must be 8-bit grey or BGR");
  GreyPair grey{left, right};
  if (left.channels() == 3) {
    cv::cvtColor(left, grey.left, cv::COLOR_BGR2GRAY);
    cv::cvtColor(right, grey.right, cv::COLOR_BGR2GRAY);
  }
  return grey;
}

cv::Mat compute_disparity(cv::StereoMatcher& matcher, const cv::Mat& left, const cv::Mat& right) {
  const GreyPair grey = grey_pair(left, right);
  cv::Mat disparity;
  matcher.compute(grey.left, grey.right, disparity);
  return disparity;
}

pcl::PointCloud<pcl::PointXYZ>::Ptr reproject(const cv::Mat& disparity16, const msg::StereoCalibration& c,
                                              double min_depth, double max_depth, int step, const cv::Mat& mask) {
  CV_Assert(disparity16.type() == CV_16S);
  CV_Assert(mask.empty() || (mask.type() == CV_8U && mask.size() == disparity16.size()));
  auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  const double fb = c.fx * c.baseline_m;
  // Valid disparities for the depth range: Z = f b / d.
  const double d_min = fb / max_depth, d_max = fb / min_depth;
  cloud->reserve(static_cast<std::size_t>(disparity16.total() / static_cast<std::size_t>(step * step) / 2));
  for (int v = 0; v < disparity16.rows; v += step) {
    const short* row = disparity16.ptr<short>(v);
    const std::uint8_t* keep = mask.empty() ? nullptr : mask.ptr<std::uint8_t>(v);
    for (int u = 0; u < disparity16.cols; u += step) {
      if (row[u] <= 0) continue;  // invalid (OpenCV marks them (min_disparity - 1) * 16)
      if (keep && !keep[u]) continue;
      const double d = row[u] / 16.0;
      if (d < d_min || d > d_max) continue;
      const double scale = c.baseline_m / d;
      cloud->push_back(pcl::PointXYZ(static_cast<float>(scale * (u - c.cx)),
                                     static_cast<float>(scale * (v - c.cy) * c.fx / c.fy), static_cast<float>(fb / d)));
    }
  }
  cloud->width = static_cast<std::uint32_t>(cloud->size());
  cloud->height = 1;
  cloud->is_dense = true;
  return cloud;
}

MatcherOptions options_for_downscale(MatcherOptions options, int factor) {
  options.num_disparities = std::max(16, (options.num_disparities / factor + 15) / 16 * 16);
  options.speckle_window_size /= factor * factor;
  return options;
}

ScaledPair downscale(const cv::Mat& left, const cv::Mat& right, const msg::StereoCalibration& c, int factor) {
  if (factor < 1) throw Error("downscale factor must be at least 1");
  if (factor == 1) return {left, right, c};
  ScaledPair out;
  const double s = 1.0 / factor;
  cv::resize(left, out.left, cv::Size(), s, s, cv::INTER_AREA);
  cv::resize(right, out.right, cv::Size(), s, s, cv::INTER_AREA);
  out.calibration = c;
  out.calibration.width = out.left.cols;
  out.calibration.height = out.left.rows;
  out.calibration.fx = c.fx * s;
  out.calibration.fy = c.fy * s;
  // Pixel centres: original pixel u maps to (u + 0.5) / factor - 0.5.
  out.calibration.cx = (c.cx + 0.5) * s - 0.5;
  out.calibration.cy = (c.cy + 0.5) * s - 0.5;
  return out;
}

cv::Mat colourise_disparity(const cv::Mat& disparity16, int num_disparities) {
  cv::Mat scaled;
  disparity16.convertTo(scaled, CV_8U, 255.0 / (16.0 * num_disparities));
  cv::Mat colour;
  cv::applyColorMap(scaled, colour, cv::COLORMAP_TURBO);
  colour.setTo(cv::Scalar(0, 0, 0), disparity16 <= 0);
  return colour;
}

}  // namespace kestrel::stereo
