#pragma once
// ROS 2's names on the DDS wire (the ROS 2 design article "Topic and Service name mapping to DDS"
// and rmw_cyclonedds_cpp): a topic /a/b is the DDS topic "rt/a/b", and a message type
// pkg/msg/Type is the DDS type "pkg::msg::dds_::Type_". A ROS 2 node finds kestrel's topics, and
// kestrel finds a ROS 2 node's, by these names alone.
#include <optional>
#include <string>
#include <string_view>

namespace kestrel::dds {

/// "/camera/frame/left" -> "rt/camera/frame/left". Throws kestrel::Error for a name ROS 2 refuses
/// (not absolute, an empty or trailing token, a character other than letters, digits and '_', a
/// token starting with a digit), saying which.
std::string ros2_dds_topic(std::string_view ros_topic);

/// "rt/camera/frame/left" -> "/camera/frame/left"; nullopt for a DDS topic that is no ROS 2 topic.
std::optional<std::string> ros2_topic_of(std::string_view dds_topic);

/// "sensor_msgs/msg/Image" -> "sensor_msgs::msg::dds_::Image_". Throws kestrel::Error for a name
/// that is not "pkg/msg/Type".
std::string ros2_dds_type(std::string_view ros_type);

/// "sensor_msgs::msg::dds_::Image_" -> "sensor_msgs/msg/Image"; nullopt for another type name.
std::optional<std::string> ros2_type_of(std::string_view dds_type);

}  // namespace kestrel::dds
