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
};

}  // namespace kestrel::msg

KESTREL_MESSAGE(kestrel::msg::PointCloud, "kestrel.PointCloud", "PCL XYZ point cloud with capture stamp and frame");
KESTREL_MESSAGE_FIELDS(
    kestrel::msg::PointCloud, {"stamp", "Time", "ns", "", "capture time of the images the points came from"},
    {"frame", "string", "", "", "the points' frame: \"camera\" (optical: x right, y down, z forward)"},
    {"points", "pcl::PointCloud<pcl::PointXYZ>::ConstPtr", "m", "in frame", "the points; shared, never modified"});
