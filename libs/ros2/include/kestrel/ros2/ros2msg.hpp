#pragma once
// ROS 2 message definitions as MCAP's `ros2msg` schema encoding carries them: the message's own
// .msg text, then each type it depends on after a line of 80 '=' and a line "MSG: pkg/Type", as
// rosbag2 and the ROS 2 tools write them.
#include <map>
#include <string>
#include <vector>

#include "kestrel/error.hpp"

namespace kestrel::ros2 {

/// A schema text that is not a valid ros2msg definition; the message names the line.
class SchemaError : public Error {
 public:
  using Error::Error;
};

struct FieldType {
  std::string name;         ///< a primitive ("float64", "string", ...) or a message "pkg/Type"
  bool is_message = false;  ///< a nested message, not a primitive
  enum class Array { none, sequence, fixed } array = Array::none;
  std::size_t length = 0;  ///< fixed arrays: their length; bounded sequences: the bound (0: none)
};

struct Field {
  std::string name;
  FieldType type;
};

struct Constant {
  std::string type, name, value;
};

struct MessageDefinition {
  std::string name;  ///< "pkg/Type"
  std::vector<Field> fields;
  std::vector<Constant> constants;  ///< declared with '=', not serialized
};

/// The definitions of one schema: the root message and every type it depends on.
class MessageSchema {
 public:
  /// `name` is the schema's name ("sensor_msgs/msg/Image" or "sensor_msgs/Image"). Throws
  /// SchemaError for a line it cannot read or a type it depends on but does not define.
  MessageSchema(const std::string& name, const std::string& text);

  const MessageDefinition& root() const { return definitions_.at(root_); }
  /// A type the root depends on, by "pkg/Type" or "pkg/msg/Type".
  const MessageDefinition& definition(const std::string& name) const;

  /// "pkg/msg/Type" or "pkg/Type" as "pkg/Type".
  static std::string normalise(const std::string& name);

 private:
  std::string root_;
  std::map<std::string, MessageDefinition> definitions_;
};

/// Whether a primitive type name is one CDR encodes; its size in bytes (strings: 0).
bool is_primitive(const std::string& type);
std::size_t primitive_size(const std::string& type);

}  // namespace kestrel::ros2
