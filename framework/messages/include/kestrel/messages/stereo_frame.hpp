#pragma once
// A rectified stereo image pair with the calibration needed to triangulate it.
#include <opencv2/core/mat.hpp>

#include "kestrel/message.hpp"

namespace kestrel::msg {

/// Rectified pinhole calibration shared by both images (rectification makes them equal).
struct StereoCalibration {
  int width = 640;
  int height = 480;
  double fx = 452.0;  ///< focal length, px
  double fy = 452.0;
  double cx = 320.0;  ///< principal point, px
  double cy = 240.0;
  double baseline_m = 0.12;  ///< distance between the optical centres
};

struct StereoFrame {
  Time stamp{0};  ///< capture time
  std::uint64_t frame_index = 0;
  cv::Mat left;   ///< rectified, CV_8UC1 or CV_8UC3
  cv::Mat right;  ///< rectified, same size and type as left
  StereoCalibration calibration;
};

}  // namespace kestrel::msg

KESTREL_MESSAGE(kestrel::msg::StereoFrame, "kestrel.StereoFrame",
                "rectified left and right images, capture stamp and calibration");
