#include "overlay.hpp"

#include <fmt/format.h>

#include <opencv2/imgproc.hpp>

namespace kestrel::video {

namespace {
const cv::Scalar kDetection(0, 200, 255), kTrack(255, 160, 0), kTarget(0, 0, 255), kAim(0, 255, 0);
}

std::optional<cv::Point2d> project(const Eigen::Vector3d& p, const msg::StereoCalibration& c) {
  if (!(p.z() > 1e-6)) return std::nullopt;
  return cv::Point2d(c.fx * p.x() / p.z() + c.cx, c.fy * p.y() / p.z() + c.cy);
}

cv::Mat draw_overlay(const msg::StereoFrame& frame, const msg::Detections* detections, const msg::Tracks* tracks,
                     const OverlayStyle& style) {
  cv::Mat image;
  if (frame.left.channels() == 1)
    cv::cvtColor(frame.left, image, cv::COLOR_GRAY2BGR);
  else
    image = frame.left.clone();
  const auto& c = frame.calibration;
  // The aim point and the net's reach around it, as seen at its depth.
  if (const auto aim = project(style.aim_point_m, c)) {
    const int radius = static_cast<int>(std::lround(c.fx * style.capture_radius_m / style.aim_point_m.z()));
    cv::circle(image, *aim, radius, kAim, 1, cv::LINE_AA);
    cv::drawMarker(image, *aim, kAim, cv::MARKER_CROSS, 16, 1, cv::LINE_AA);
  }
  if (detections)
    for (const auto& d : detections->items) {
      const auto a = project(d.position - 0.5 * d.extent, c), b = project(d.position + 0.5 * d.extent, c);
      if (a && b) cv::rectangle(image, *a, *b, kDetection, 1, cv::LINE_AA);
    }
  if (tracks)
    for (const auto& t : tracks->items) {
      const auto p = project(t.position(), c);
      if (!p) continue;
      const bool target = tracks->selected_id && *tracks->selected_id == t.id;
      cv::circle(image, *p, target ? 10 : 6, target ? kTarget : kTrack, target ? 2 : 1, cv::LINE_AA);
      cv::putText(image, fmt::format("{}{}", target ? "target " : "", t.id), *p + cv::Point2d(10, -10),
                  cv::FONT_HERSHEY_SIMPLEX, 0.4, target ? kTarget : kTrack, 1, cv::LINE_AA);
    }
  return image;
}

}  // namespace kestrel::video
