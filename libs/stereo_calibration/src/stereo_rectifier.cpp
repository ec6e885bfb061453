#include "kestrel/stereo_calibration/stereo_rectifier.hpp"

#include <cmath>
#include <kestrel/error.hpp>
#include <opencv2/calib3d.hpp>
#include <opencv2/core/persistence.hpp>
#include <opencv2/imgproc.hpp>

namespace kestrel::calibration {

namespace {

cv::Matx33d k_of(const CameraInfo& c) { return cv::Matx33d(c.k.data()); }
cv::Matx33d r_of(const CameraInfo& c) { return cv::Matx33d(c.r.data()); }
cv::Matx33d p_intrinsics(const CameraInfo& c) {
  return cv::Matx33d(c.p[0], c.p[1], c.p[2], c.p[4], c.p[5], c.p[6], c.p[8], c.p[9], c.p[10]);
}

void maps(const CameraInfo& c, cv::Mat& map1, cv::Mat& map2) {
  const cv::Size size(c.width, c.height);
  const cv::Mat d(c.d, true);
  if (c.distortion_model == "equidistant")
    cv::fisheye::initUndistortRectifyMap(k_of(c), d.rowRange(0, 4), r_of(c), p_intrinsics(c), size, CV_16SC2, map1,
                                         map2);
  else
    cv::initUndistortRectifyMap(k_of(c), d, r_of(c), p_intrinsics(c), size, CV_16SC2, map1, map2);
}

// Rectified image coordinates of raw pixels.
std::vector<cv::Point2f> rectified_points(const CameraInfo& c, const std::vector<cv::Point2f>& raw) {
  std::vector<cv::Point2f> out;
  if (raw.empty()) return out;
  const cv::Mat d(c.d, true);
  if (c.distortion_model == "equidistant")
    cv::fisheye::undistortPoints(raw, out, k_of(c), d.rowRange(0, 4), r_of(c), p_intrinsics(c));
  else
    cv::undistortPoints(raw, out, k_of(c), d, r_of(c), p_intrinsics(c));
  return out;
}

}  // namespace

StereoRectifier::StereoRectifier(const CameraInfo& left, const CameraInfo& right) {
  if (left.width != right.width || left.height != right.height)
    throw Error("the left camera_info is " + std::to_string(left.width) + "x" + std::to_string(left.height) +
                " and the right " + std::to_string(right.width) + "x" + std::to_string(right.height));
  // Rectification gives both cameras one set of intrinsics; only the right P's Tx differs.
  const double tolerance = 1e-6 * left.p[0];
  for (int i : {0, 2, 5, 6})
    if (std::abs(left.p[static_cast<std::size_t>(i)] - right.p[static_cast<std::size_t>(i)]) > tolerance)
      throw Error("the left and right projection matrices have other intrinsics (P[" + std::to_string(i) +
                  "]: " + std::to_string(left.p[static_cast<std::size_t>(i)]) + " and " +
                  std::to_string(right.p[static_cast<std::size_t>(i)]) + "): not one rectified pair");
  if (left.p[3] != 0.0)
    throw Error("the left projection matrix has Tx = " + std::to_string(left.p[3]) +
                ": left and right camera_info files swapped?");
  if (!(right.p[3] < 0.0))
    throw Error("the right projection matrix has no baseline (Tx = " + std::to_string(right.p[3]) +
                ", it must be -fx * baseline < 0)");
  calibration_.width = left.width;
  calibration_.height = left.height;
  calibration_.fx = left.p[0];
  calibration_.fy = left.p[5];
  calibration_.cx = left.p[2];
  calibration_.cy = left.p[6];
  calibration_.baseline_m = -right.p[3] / right.p[0];
  passthrough_ = left.rectified() && right.rectified();
  if (passthrough_) return;
  maps(left, left_map1_, left_map2_);
  maps(right, right_map1_, right_map2_);
}

void StereoRectifier::rectify(const cv::Mat& left_raw, const cv::Mat& right_raw, cv::Mat& left, cv::Mat& right) const {
  const cv::Size size(calibration_.width, calibration_.height);
  if (left_raw.size() != size || right_raw.size() != size)
    throw Error("a " + std::to_string(left_raw.cols) + "x" + std::to_string(left_raw.rows) +
                " pair for a calibration of " + std::to_string(size.width) + "x" + std::to_string(size.height));
  if (passthrough_) {
    left = left_raw;
    right = right_raw;
    return;
  }
  cv::remap(left_raw, left, left_map1_, left_map2_, cv::INTER_LINEAR, cv::BORDER_CONSTANT);
  cv::remap(right_raw, right, right_map1_, right_map2_, cv::INTER_LINEAR, cv::BORDER_CONSTANT);
}

std::pair<CameraInfo, CameraInfo> camera_infos(const StereoRig& rig) {
  cv::Mat r1, r2, p1, p2, q;
  cv::stereoRectify(rig.k_left, cv::Mat(rig.d_left), rig.k_right, cv::Mat(rig.d_right), {rig.width, rig.height}, rig.r,
                    rig.t, r1, r2, p1, p2, q, cv::CALIB_ZERO_DISPARITY, 0);
  auto info = [&](const char* name, const cv::Matx33d& k, const std::vector<double>& d, const cv::Mat& r,
                  const cv::Mat& p) {
    CameraInfo c;
    c.width = rig.width;
    c.height = rig.height;
    c.camera_name = name;
    std::copy(k.val, k.val + 9, c.k.begin());
    c.distortion_model = d.size() > 5 ? "rational_polynomial" : "plumb_bob";
    c.d = d;
    c.d.resize(std::max<std::size_t>(d.size(), 5), 0.0);
    for (int i = 0; i < 9; ++i) c.r[static_cast<std::size_t>(i)] = r.at<double>(i / 3, i % 3);
    for (int i = 0; i < 12; ++i) c.p[static_cast<std::size_t>(i)] = p.at<double>(i / 4, i % 4);
    return c;
  };
  return {info("left", rig.k_left, rig.d_left, r1, p1), info("right", rig.k_right, rig.d_right, r2, p2)};
}

StereoRig load_opencv_stereo(const std::string& path) {
  cv::FileStorage fs;
  try {
    if (!fs.open(path, cv::FileStorage::READ)) throw Error("cannot read the OpenCV calibration file " + path);
  } catch (const cv::Exception& e) {
    throw Error(path + " is not an OpenCV calibration file: " + e.msg);
  }
  auto mat = [&](std::initializer_list<const char*> names, int rows, int cols) {
    for (const char* name : names) {
      cv::Mat m;
      fs[name] >> m;
      if (m.empty()) continue;
      m.convertTo(m, CV_64F);
      if ((rows > 0 && m.rows != rows) || (cols > 0 && m.cols != cols && m.total() != static_cast<std::size_t>(cols)))
        throw Error(path + ": " + name + " is " + std::to_string(m.rows) + "x" + std::to_string(m.cols));
      return m;
    }
    throw Error(path + " has no " + std::string(*names.begin()) +
                " (an OpenCV stereo calibration holds K1, D1, K2, "
                "D2, R, T, image_width and image_height)");
  };
  StereoRig rig;
  const cv::Mat k1 = mat({"K1", "M1"}, 3, 3), k2 = mat({"K2", "M2"}, 3, 3), r = mat({"R"}, 3, 3), t = mat({"T"}, -1, 3);
  const cv::Mat d1 = mat({"D1"}, -1, -1), d2 = mat({"D2"}, -1, -1);
  rig.k_left = cv::Matx33d(k1);
  rig.k_right = cv::Matx33d(k2);
  rig.r = cv::Matx33d(r);
  rig.t = cv::Vec3d(t.at<double>(0), t.at<double>(1), t.at<double>(2));
  rig.d_left.assign(d1.begin<double>(), d1.end<double>());
  rig.d_right.assign(d2.begin<double>(), d2.end<double>());
  fs["image_width"] >> rig.width;
  fs["image_height"] >> rig.height;
  if (rig.width <= 0 || rig.height <= 0) throw Error(path + " has no image_width and image_height");
  return rig;
}

EpipolarError epipolar_error(const CameraInfo& left, const CameraInfo& right, const std::vector<cv::Point2f>& left_raw,
                             const std::vector<cv::Point2f>& right_raw) {
  if (left_raw.size() != right_raw.size()) throw Error("epipolar_error needs as many left points as right ones");
  const auto l = rectified_points(left, left_raw), r = rectified_points(right, right_raw);
  EpipolarError e;
  for (std::size_t i = 0; i < l.size(); ++i) {
    const double dy = std::abs(static_cast<double>(l[i].y) - static_cast<double>(r[i].y));
    e.mean_px += dy;
    e.max_px = std::max(e.max_px, dy);
  }
  if (!l.empty()) e.mean_px /= static_cast<double>(l.size());
  return e;
}

}  // namespace kestrel::calibration
