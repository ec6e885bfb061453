#pragma once
// A 3D point cloud (PCL), in a named frame.
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <string>

#include "kestrel/message.hpp"

namespace kestrel::msg {

struct PointCloud {
  Time stamp{0};                 ///< capture time of the data the points came from
  std::string frame = "camera";  ///< camera: x right, y down, z forward (optical frame)
  pcl::PointCloud<pcl::PointXYZ>::ConstPtr points;
  /// Points made one per image sample (stereo_depth): each stands for a square of this many
  /// full-resolution pixels a side of the left image, centred where it projects (1: one pixel,
  /// 2: matched at half resolution). 0: the points are not image samples (a voxel grid's).
  int pixels_per_point = 0;
  /// Points from stereo (stereo_depth, and filters that keep them): the matched images' fx times
  /// the baseline, so that depth = focal_baseline / disparity, and a disparity error of e px
  /// moves a point at depth z by z^2 e / focal_baseline along its ray. 0: not from stereo.
  double focal_baseline_px_m = 0.0;
};

}  // namespace kestrel::msg

KESTREL_MESSAGE(kestrel::msg::PointCloud, "kestrel.PointCloud", "PCL XYZ point cloud with capture stamp and frame");
KESTREL_MESSAGE_FIELDS(
    kestrel::msg::PointCloud, {"stamp", "Time", "ns", "", "capture time of the images the points came from"},
    {"frame", "string", "", "", "the points' frame: \"camera\" (optical: x right, y down, z forward)"},
    {"points", "pcl::PointCloud<pcl::PointXYZ>::ConstPtr", "m", "in frame", "the points; shared, never modified"},
    {"pixels_per_point", "int", "px", "",
     "image samples: the side of the square of full-resolution left-image pixels each point stands for; 0: not "
     "image samples"},
    {"focal_baseline_px_m", "double", "px*m", "",
     "stereo points: the matched images' fx times the baseline (depth = focal_baseline / disparity); 0: not from "
     "stereo"});
