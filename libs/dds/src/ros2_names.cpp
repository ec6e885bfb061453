#include "kestrel/dds/ros2_names.hpp"

#include <cctype>
#include <kestrel/error.hpp>

namespace kestrel::dds {
namespace {

bool is_token_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

}  // namespace

std::string ros2_dds_topic(std::string_view ros_topic) {
  const std::string quoted = "ROS 2 topic '" + std::string(ros_topic) + "'";
  if (ros_topic.empty() || ros_topic.front() != '/') throw Error(quoted + " must start with '/'");
  if (ros_topic.size() == 1) throw Error(quoted + " names nothing");
  if (ros_topic.back() == '/') throw Error(quoted + " must not end with '/'");
  std::size_t token_start = 1;
  for (std::size_t i = 1; i <= ros_topic.size(); ++i) {
    if (i == ros_topic.size() || ros_topic[i] == '/') {
      if (i == token_start) throw Error(quoted + " has an empty token ('//')");
      if (std::isdigit(static_cast<unsigned char>(ros_topic[token_start])) != 0)
        throw Error(quoted + ": a token must not start with a digit ('" +
                    std::string(ros_topic.substr(token_start, i - token_start)) + "')");
      token_start = i + 1;
    } else if (!is_token_char(ros_topic[i])) {
      throw Error(quoted + ": '" + std::string(1, ros_topic[i]) +
                  "' is not allowed (letters, digits and '_' only, tokens separated by '/')");
    }
  }
  return "rt" + std::string(ros_topic);
}

std::optional<std::string> ros2_topic_of(std::string_view dds_topic) {
  if (!dds_topic.starts_with("rt/") || dds_topic.size() < 4) return std::nullopt;
  return std::string(dds_topic.substr(2));
}

std::string ros2_dds_type(std::string_view ros_type) {
  const auto first = ros_type.find('/');
  const auto last = ros_type.rfind('/');
  if (first == std::string_view::npos || first == 0 || last == ros_type.size() - 1 ||
      ros_type.substr(first, last - first + 1) != "/msg/")
    throw Error("'" + std::string(ros_type) + "' is not a ROS 2 message type (pkg/msg/Type)");
  return std::string(ros_type.substr(0, first)) + "::msg::dds_::" + std::string(ros_type.substr(last + 1)) + "_";
}

std::optional<std::string> ros2_type_of(std::string_view dds_type) {
  constexpr std::string_view kMiddle = "::msg::dds_::";
  const auto middle = dds_type.find(kMiddle);
  if (middle == std::string_view::npos || middle == 0 || !dds_type.ends_with('_')) return std::nullopt;
  const auto type = dds_type.substr(middle + kMiddle.size());
  if (type.size() < 2) return std::nullopt;
  return std::string(dds_type.substr(0, middle)) + "/msg/" + std::string(type.substr(0, type.size() - 1));
}

}  // namespace kestrel::dds
