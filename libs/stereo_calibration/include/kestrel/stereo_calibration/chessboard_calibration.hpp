#pragma once
// Stereo calibration from chessboard pairs with OpenCV, for `kestrel calibrate`: the corners found
// in each pair (sub-pixel), each camera calibrated alone, then the pair with its intrinsics held
// (stereoCalibrate), and rectified as camera_calibration does. The result is the camera_info
// pair every driver reads, with the errors that tell a good calibration from a bad one.
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "kestrel/stereo_calibration/camera_info.hpp"
#include "kestrel/stereo_calibration/stereo_rectifier.hpp"

namespace kestrel::calibration {

struct ChessboardOptions {
  cv::Size inner_corners{8, 6};  ///< corners where four squares meet, along and across
  double square_m = 0.025;       ///< side of a square
};

struct ChessboardCalibration {
  StereoRig rig;
  CameraInfo left, right;
  double rms_px = 0.0;     ///< stereoCalibrate's reprojection error
  EpipolarError epipolar;  ///< of the corners, after rectification
  std::size_t pairs_used = 0;
  std::vector<std::string> skipped;  ///< pairs whose board was not found in both images, and why
};

/// Calibrates from grey (or colour) image pairs of one size; `names` label them in `skipped`.
/// Throws kestrel::Error when fewer than 5 pairs show the whole board in both images.
ChessboardCalibration calibrate_stereo(const std::vector<std::pair<cv::Mat, cv::Mat>>& pairs,
                                       const std::vector<std::string>& names, const ChessboardOptions& options);

}  // namespace kestrel::calibration
