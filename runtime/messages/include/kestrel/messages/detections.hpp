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
KESTREL_MESSAGE_FIELDS(kestrel::msg::Detections,
                       {"stamp", "Time", "ns", "", "capture time of the frame they were found in"},
                       {"frame", "string", "", "", "frame of the positions: \"camera\""},
                       {"items", "vector<Detection>", "", "", "one per object; may be empty"},
                       {"items[].position", "Eigen::Vector3d", "m", "in frame", "centroid"},
                       {"items[].extent", "Eigen::Vector3d", "m", "in frame", "size of the axis-aligned bounding box"},
                       {"items[].point_count", "int", "", "", "points in the cluster; 0 for a made-up detection"},
                       {"items[].confidence", "double", "", "", "0 to 1; 1 when the detector gives none"});
