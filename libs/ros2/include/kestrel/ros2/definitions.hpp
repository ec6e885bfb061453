#pragma once
// The ROS 2 message definitions kestrel writes: the standard types its messages map onto
// (std_msgs, geometry_msgs, sensor_msgs, nav_msgs, tf2_msgs, visualization_msgs, as ROS 2 Humble
// defines them) and the kestrel_msgs types for what has no standard equivalent.
#include <string>
#include <vector>

namespace kestrel::ros2 {

/// The ros2msg schema text of `name` ("sensor_msgs/msg/Image" or "sensor_msgs/Image"): its own
/// definition, then each type it depends on once, depth first, after a line of 80 '=' and a line
/// "MSG: pkg/Type", as rosbag2 writes them. Throws kestrel::Error for a type it does not define.
const std::string& schema_text(const std::string& name);

/// Every type defined here, as "pkg/msg/Type".
std::vector<std::string> defined_types();

}  // namespace kestrel::ros2
