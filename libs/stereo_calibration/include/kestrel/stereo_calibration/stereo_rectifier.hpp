#pragma once
// Turns raw stereo pairs into the rectified ones every kestrel stage expects, from a left and
// right CameraInfo: the undistort-and-rectify maps are computed once (fixed-point, for a fast
// remap), and the rectified camera is read from the projections P, as ROS's stereo_image_proc
// reads it (fx, fy, cx, cy from the left P, baseline = -Tx / fx from the right one).
#include <kestrel/messages/stereo_frame.hpp>
#include <opencv2/core.hpp>

#include "kestrel/stereo_calibration/camera_info.hpp"

namespace kestrel::calibration {

class StereoRectifier {
 public:
  /// Throws kestrel::Error when the two do not describe one rectified pair: other image sizes,
  /// rectified intrinsics that differ, a right P with no baseline, a left P with one.
  StereoRectifier(const CameraInfo& left, const CameraInfo& right);

  /// The rectified pair's calibration, as a StereoFrame carries it.
  const msg::StereoCalibration& calibration() const { return calibration_; }
  /// True when both images are rectified already: rectify() then only checks their size.
  bool passthrough() const { return passthrough_; }

  /// Rectifies one pair (grey or colour, of the calibrated size); throws kestrel::Error on
  /// another size.
  void rectify(const cv::Mat& left_raw, const cv::Mat& right_raw, cv::Mat& left, cv::Mat& right) const;

 private:
  msg::StereoCalibration calibration_;
  bool passthrough_ = false;
  cv::Mat left_map1_, left_map2_, right_map1_, right_map2_;
};

/// A stereo rig as OpenCV's stereoCalibrate describes it: each camera's K and D, and the right
/// camera's pose in the left's (x_right = R x_left + T, metres).
struct StereoRig {
  int width = 0, height = 0;
  cv::Matx33d k_left, k_right;
  std::vector<double> d_left, d_right;  ///< plumb_bob or rational coefficients
  cv::Matx33d r;
  cv::Vec3d t;
};

/// The camera_info pair of a rig, as camera_calibration writes it: OpenCV's stereoRectify with
/// the whole valid image kept (alpha 0) and the principal points made equal.
std::pair<CameraInfo, CameraInfo> camera_infos(const StereoRig& rig);

/// Reads an OpenCV FileStorage file (YAML, XML or JSON) of a stereo calibration: K1 and K2 (or
/// M1 and M2), D1, D2, R, T, and image_width and image_height. Throws Error naming what is
/// missing.
StereoRig load_opencv_stereo(const std::string& path);

/// The rectified epipolar error of matched points: |y_left - y_right| in rectified pixels, mean
/// and largest, for `kestrel calibrate` and the tests. Points are raw pixel coordinates.
struct EpipolarError {
  double mean_px = 0.0;
  double max_px = 0.0;
};
EpipolarError epipolar_error(const CameraInfo& left, const CameraInfo& right, const std::vector<cv::Point2f>& left_raw,
                             const std::vector<cv::Point2f>& right_raw);

}  // namespace kestrel::calibration
