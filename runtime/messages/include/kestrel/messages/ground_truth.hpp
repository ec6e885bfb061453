#pragma once
// What a simulator knows for certain, published beside the sensor data for evaluators.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "kestrel/message.hpp"

namespace kestrel::msg {

struct GroundTruthObject {
  std::uint64_t id = 0;
  Eigen::Vector3d position_world = Eigen::Vector3d::Zero();   ///< metres
  Eigen::Vector3d position_camera = Eigen::Vector3d::Zero();  ///< optical frame, metres
  Eigen::Vector3d velocity_world = Eigen::Vector3d::Zero();   ///< m/s
  bool in_view = true;                                        ///< inside the camera's field of view and depth range
};

struct GroundTruth {
  Time stamp{0};  ///< the sensor capture this truth belongs to
  std::vector<GroundTruthObject> objects;
};

}  // namespace kestrel::msg

KESTREL_MESSAGE(kestrel::msg::GroundTruth, "kestrel.GroundTruth",
                "true object positions (world and camera frames) at a capture time");
KESTREL_MESSAGE_FIELDS(kestrel::msg::GroundTruth, {"stamp", "Time", "ns", "", "the capture this truth belongs to"},
                       {"objects", "vector<GroundTruthObject>", "", "", "every simulated intruder"},
                       {"objects[].id", "uint64", "", "", "the intruder's id, unique in a run"},
                       {"objects[].position_world", "Eigen::Vector3d", "m", "world", "position"},
                       {"objects[].position_camera", "Eigen::Vector3d", "m", "camera",
                        "position in the optical frame of the publishing camera"},
                       {"objects[].velocity_world", "Eigen::Vector3d", "m/s", "world", "velocity"},
                       {"objects[].in_view", "bool", "", "", "inside the camera's field of view and depth range"});
