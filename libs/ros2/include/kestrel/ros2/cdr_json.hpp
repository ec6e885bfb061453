#pragma once
// Any ROS 2 message as JSON, decoded from its CDR bytes by its ros2msg schema alone, as Foxglove
// decodes messages it has no code for: `kestrel mcap cat` reads any ROS 2 bag this way.
#include <nlohmann/json.hpp>
#include <span>

#include "kestrel/ros2/cdr.hpp"
#include "kestrel/ros2/ros2msg.hpp"

namespace kestrel::ros2 {

/// Fields by name in declaration order; numbers as numbers (64-bit integers exactly, NaN and
/// infinities as null), strings as strings, arrays (uint8[] too) as arrays. Throws CdrError when
/// the bytes do not hold a message of that schema, or hold more than one.
nlohmann::ordered_json cdr_to_json(const MessageSchema& schema, std::span<const std::uint8_t> cdr);

}  // namespace kestrel::ros2
