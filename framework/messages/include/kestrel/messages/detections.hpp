#pragma once
// Objects detected in one sensor frame.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "kestrel/message.hpp"

namespace kestrel::msg {

struct Detection {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< centroid, metres, in `frame`
  Eigen::Vector3d extent = Eigen::Vector3d::Zero();    ///< bounding-box size, metres
  int point_count = 0;
  double confidence = 1.0;
};

struct Detections {
  Time stamp{0};  ///< capture time of the frame they were found in
  std::string frame = "camera";
  std::vector<Detection> items;
};

}  // namespace kestrel::msg

KESTREL_MESSAGE(kestrel::msg::Detections, "kestrel.Detections",
                "detections of one frame: centroid, extent, point count");
