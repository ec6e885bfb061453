#pragma once
// Errors read in the hunter's body axes. Evaluators measure in the camera's optical frame (x
// right, y down, z depth); the paper's Table 1, like its simulator (RotorS), gives them in the
// body frame (FLU: x forward = depth, y left, z up). The same figures, with the axes renamed
// and the signs of x and y turned: report.json carries both (`rmse_m`, `rmse_body_m`).
#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <optional>

#include "kestrel/geometry/frames.hpp"

namespace kestrel::evaluation {

/// Per-axis RMS errors (magnitudes) of the camera's axes, on the body's.
inline Eigen::Vector3d rms_in_body_axes(const Eigen::Vector3d& rms_camera) {
  return (geometry::body_from_camera() * rms_camera).cwiseAbs();
}

/// A signed error (a bias) of the camera's axes, on the body's.
inline Eigen::Vector3d bias_in_body_axes(const Eigen::Vector3d& bias_camera) {
  return geometry::body_from_camera() * bias_camera;
}

/// {x, y, z} of a per-axis figure, or three nulls where it is undefined.
inline nlohmann::json axes_or_null(const std::optional<Eigen::Vector3d>& v) {
  if (!v) return {{"x", nullptr}, {"y", nullptr}, {"z", nullptr}};
  return {{"x", v->x()}, {"y", v->y()}, {"z", v->z()}};
}

}  // namespace kestrel::evaluation
