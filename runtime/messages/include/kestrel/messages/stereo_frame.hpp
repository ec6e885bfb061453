#pragma once
// A rectified stereo image pair with the calibration needed to triangulate it.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <opencv2/core/mat.hpp>
#include <string>

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

/// Where the camera stands: the pose of the left camera's optical frame ("camera": x right, y
/// down, z forward) in the frame that carries it. Recordings and the live view publish it on /tf,
/// so that viewers place what the camera sees beside the vehicles.
struct CameraMount {
  /// "world" for a fixed camera, or the body frame of the vehicle carrying it: the id of the node
  /// whose VehicleState gives that vehicle's /tf frame ("hunter").
  std::string parent_frame = "world";
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< optical centre in the parent frame, m
  /// Rotates camera-frame vectors into the parent frame. The default is a level camera looking
  /// along the parent's x (geometry::body_from_camera()).
  Eigen::Quaterniond orientation{0.5, -0.5, 0.5, -0.5};
};

struct StereoFrame {
  Time stamp{0};  ///< capture time
  std::uint64_t frame_index = 0;
  cv::Mat left;   ///< rectified, CV_8UC1 or CV_8UC3
  cv::Mat right;  ///< rectified, same size and type as left
  StereoCalibration calibration;
  CameraMount mount;
};

}  // namespace kestrel::msg

KESTREL_MESSAGE(kestrel::msg::StereoFrame, "kestrel.StereoFrame",
                "rectified left and right images, capture stamp and calibration");
KESTREL_MESSAGE_FIELDS(kestrel::msg::StereoFrame, {"stamp", "Time", "ns", "", "capture time"},
                       {"frame_index", "uint64", "", "", "count of frames from this camera, from 0"},
                       {"left", "cv::Mat", "", "", "rectified left image, CV_8UC1 (grey) or CV_8UC3 (BGR)"},
                       {"right", "cv::Mat", "", "", "rectified right image, same size and type as left"},
                       {"calibration.width", "int", "px", "", "image width"},
                       {"calibration.height", "int", "px", "", "image height"},
                       {"calibration.fx", "double", "px", "", "horizontal focal length"},
                       {"calibration.fy", "double", "px", "", "vertical focal length"},
                       {"calibration.cx", "double", "px", "", "principal point, column"},
                       {"calibration.cy", "double", "px", "", "principal point, row"},
                       {"calibration.baseline_m", "double", "m", "", "distance between the optical centres"},
                       {"mount.parent_frame", "string", "", "", "frame carrying the camera: world or a vehicle's"},
                       {"mount.position", "Eigen::Vector3d", "m", "parent", "left optical centre"},
                       {"mount.orientation", "Eigen::Quaterniond", "", "camera to parent",
                        "rotates camera-frame vectors into the parent frame"});
