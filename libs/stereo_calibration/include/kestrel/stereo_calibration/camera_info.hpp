#pragma once
// A camera's calibration as ROS describes it (sensor_msgs/CameraInfo), read from and written to
// the YAML files ROS's camera_calibration writes (camera_calibration_parsers' layout): image size,
// camera name, K, the distortion model and D, the rectification R and the projection P. The oCamS
// driver, `stereo_images` and `kestrel calibrate` share it, so one file serves them all and ROS.
#include <array>
#include <filesystem>
#include <string>
#include <vector>

namespace kestrel::calibration {

struct CameraInfo {
  int width = 0;
  int height = 0;
  std::string camera_name;
  std::array<double, 9> k{};  ///< intrinsics of the raw image, row-major
  /// "plumb_bob" (k1 k2 t1 t2 k3), "rational_polynomial" (8) or "equidistant" (fisheye, 4).
  std::string distortion_model = "plumb_bob";
  std::vector<double> d;       ///< distortion coefficients of that model
  std::array<double, 9> r{};   ///< rotation from the raw camera into the rectified one
  std::array<double, 12> p{};  ///< projection of the rectified camera; p[3] = -fx * baseline for the right one

  /// Whether images with this calibration are already rectified: no distortion, R the identity
  /// and P's intrinsics those of K.
  bool rectified() const;
};

/// Reads a camera_info YAML file. Throws kestrel::Error with file:line:col on a missing or bad
/// field (a matrix of the wrong size, a number that is not one, an unknown distortion model).
CameraInfo load_camera_info(const std::filesystem::path& file);
/// Parses camera_info YAML text; `name` stands for the file in errors.
CameraInfo parse_camera_info(const std::string& text, const std::string& name);
/// The YAML camera_calibration writes, numbers to the last bit.
std::string to_yaml(const CameraInfo& info);

}  // namespace kestrel::calibration
