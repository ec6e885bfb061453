#pragma once
// The calibration of a Middlebury stereo pair (calib.txt of the 2014 and 2021 datasets): two
// rectified cameras that differ in their principal point's x by `doffs`, a baseline in
// millimetres, the image size and the disparity range. Read into the camera_info pair the rest of
// kestrel uses, so that `stereo_images` plays the pairs.
//
//   cam0=[994.978 0 311.193; 0 994.978 254.877; 0 0 1]
//   cam1=[994.978 0 342.279; 0 994.978 254.877; 0 0 1]
//   doffs=31.086
//   baseline=193.001
//   width=741
//   height=500
//   ndisp=68
#include <filesystem>
#include <string>
#include <utility>

#include "kestrel/stereo_calibration/camera_info.hpp"

namespace kestrel::calibration {

struct MiddleburyCalibration {
  std::array<double, 9> cam0{}, cam1{};  ///< row-major intrinsics of the rectified left and right cameras
  double doffs = 0.0;                    ///< px: cam1's cx - cam0's cx; depth = baseline * f / (d + doffs)
  double baseline_mm = 0.0;
  int width = 0, height = 0;
  int ndisp = 0;  ///< a bound on the disparities (0: not given)

  /// The pair as camera_info: both rectified cameras have cam0's intrinsics (the right image is
  /// moved by doffs onto them, so disparity gives depth); the right P carries -f * baseline (m).
  std::pair<CameraInfo, CameraInfo> camera_infos() const;
};

/// Reads calib.txt; kestrel::Error with file:line on a missing or malformed entry.
MiddleburyCalibration load_middlebury_calibration(const std::filesystem::path& file);
/// Parses its text; `name` stands for the file in errors.
MiddleburyCalibration parse_middlebury_calibration(const std::string& text, const std::string& name);

}  // namespace kestrel::calibration
