#pragma once
// The pinhole camera of a rectified stereo pair: focal length from a field of view, and the
// (u, v, disparity) a point of the camera frame images to, and back. Shared by the rendered camera
// and by the detection-level camera model, so both see the same image.
#include <Eigen/Core>
#include <cmath>

#include "kestrel/messages/stereo_frame.hpp"

namespace kestrel::geometry {

/// Focal length in pixels of an image `width_px` wide spanning `hfov_deg` horizontally.
inline double focal_from_hfov(int width_px, double hfov_deg) {
  return (width_px / 2.0) / std::tan(hfov_deg * M_PI / 360.0);
}

/// Pixel column, row and disparity (px) of a camera-frame point in front of the camera (z > 0).
inline Eigen::Vector3d to_pixel_disparity(const msg::StereoCalibration& c, const Eigen::Vector3d& p_camera) {
  return {c.fx * p_camera.x() / p_camera.z() + c.cx, c.fy * p_camera.y() / p_camera.z() + c.cy,
          c.fx * c.baseline_m / p_camera.z()};
}

/// The camera-frame point a pixel with a (positive) disparity triangulates to.
inline Eigen::Vector3d from_pixel_disparity(const msg::StereoCalibration& c, const Eigen::Vector3d& uvd) {
  const double z = c.fx * c.baseline_m / uvd.z();
  return {(uvd.x() - c.cx) * z / c.fx, (uvd.y() - c.cy) * z / c.fy, z};
}

/// True when the pixel lies inside the image.
inline bool in_image(const msg::StereoCalibration& c, double u, double v) {
  return u >= 0.0 && u < c.width && v >= 0.0 && v < c.height;
}

/// True when a camera-frame point lies within [min_depth, max_depth] and images inside the picture.
inline bool in_view(const msg::StereoCalibration& c, double min_depth, double max_depth, const Eigen::Vector3d& p) {
  if (!(p.z() >= min_depth && p.z() <= max_depth)) return false;
  const Eigen::Vector3d uvd = to_pixel_disparity(c, p);
  return in_image(c, uvd.x(), uvd.y());
}

}  // namespace kestrel::geometry
