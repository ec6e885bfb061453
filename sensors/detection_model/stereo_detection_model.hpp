#pragma once
// A detection-level model of the stereo perception chain (camera, SGBM depth, voxel grid,
// Euclidean clustering): what the chain would report for an intruder, without rendering a pixel.
// For benchmarks that need many closed-loop runs; its parameters are fitted to the rendered chain
// (scripts/fit-detection-model, docs/control.md).
//
// The error has two parts. One is drawn where a stereo camera makes it: in the image column and
// row of the cluster's centroid and in its disparity, then triangulated, so it grows with the
// range (lateral) and its square (depth). The other is the cluster's centroid missing the object's
// centre (a part of the drone not matched, a part of the background bled in), a few centimetres
// whatever the range; it dominates near the camera.
#include <Eigen/Core>
#include <kestrel/messages/stereo_frame.hpp>
#include <optional>
#include <random>
#include <vector>

namespace kestrel::sensors {

struct DetectionModelParams {
  msg::StereoCalibration camera;                      ///< the camera whose chain is modelled
  double min_depth_m = 0.5;                           ///< nearer than this, nothing is detected
  double max_depth_m = 8.0;                           ///< farther than this, nothing is detected
  Eigen::Vector2d centroid_sigma_px{2.0, 2.0};        ///< image column and row of the centroid
  double disparity_sigma_px = 0.15;                   ///< the cluster's mean disparity
  double disparity_bias_px = 0.0;                     ///< added to it (> 0: detections too near)
  Eigen::Vector3d object_sigma_m{0.0, 0.0, 0.0};      ///< centroid against object centre (camera frame)
  std::vector<double> recall_depth_m{2.5, 5.0, 7.5};  ///< where the detection probability is given
  std::vector<double> recall{0.99, 0.99, 0.97};       ///< detection probability there, interpolated
  Eigen::Vector3d object_extent_m{0.5, 0.2, 0.5};     ///< the reported bounding box
};

/// Throws kestrel::Error when the parameters cannot describe a camera or a probability.
void check(const DetectionModelParams& p);

class StereoDetectionModel {
 public:
  explicit StereoDetectionModel(DetectionModelParams params);

  /// True when a point of the camera frame is in the image and within the depth range.
  bool visible(const Eigen::Vector3d& p_camera) const;
  /// Probability of detecting an object at this depth (recall table, held at its ends).
  double detection_probability(double depth_m) const;
  /// The chain's detection of an intruder whose centre is at `p_camera`: none when it is out of
  /// view or missed, else its centroid with the chain's error.
  std::optional<Eigen::Vector3d> observe(const Eigen::Vector3d& p_camera, std::mt19937_64& rng) const;

  const DetectionModelParams& params() const { return params_; }

 private:
  DetectionModelParams params_;
};

}  // namespace kestrel::sensors
