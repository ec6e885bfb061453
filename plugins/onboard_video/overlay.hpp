#pragma once
// What the onboard video shows on the left image: detections as boxes, the tracks with their
// ids, the selected target ringed, and the aim point x_E^d with the net's radius around it.
#include <Eigen/Core>
#include <kestrel/messages/detections.hpp>
#include <kestrel/messages/stereo_frame.hpp>
#include <kestrel/messages/tracks.hpp>
#include <opencv2/core.hpp>
#include <optional>

namespace kestrel::video {

/// Pixel of a camera-frame point under a rectified pinhole calibration; none behind the camera.
std::optional<cv::Point2d> project(const Eigen::Vector3d& p, const msg::StereoCalibration& c);

struct OverlayStyle {
  Eigen::Vector3d aim_point_m{0.0, 1.0, 2.0};
  double capture_radius_m = 0.5;
};

/// The left image in colour with the overlay drawn on it.
cv::Mat draw_overlay(const msg::StereoFrame& frame, const msg::Detections* detections, const msg::Tracks* tracks,
                     const OverlayStyle& style);

}  // namespace kestrel::video
