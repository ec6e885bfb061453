#pragma once
// visualization_msgs/MarkerArray for the channels viewers draw (".../markers"): one array per
// message, led by a DELETEALL so that what the last message showed goes.
#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "kestrel/time.hpp"

namespace kestrel::ros2::detail {

struct MarkerSpec {
  enum Shape : std::int32_t { arrow = 0, cube = 1, sphere = 2, text = 9 };
  Shape shape = cube;
  std::string ns;
  std::int32_t id = 0;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d scale = Eigen::Vector3d::Constant(0.1);
  std::array<float, 4> rgba = {1.0f, 1.0f, 1.0f, 1.0f};
  std::string label;  ///< text markers only
};

std::vector<std::uint8_t> marker_array(Time stamp, const std::string& frame_id, const std::vector<MarkerSpec>& markers);

}  // namespace kestrel::ros2::detail
