#pragma once
// An autopilot's answer to a command, as the tests write them.
#include <cstdint>

#include "kestrel/mavlink/messages.hpp"

namespace kestrel::mavlink::testing {

inline CommandAck ack(std::uint16_t command, std::uint8_t result) {
  CommandAck a;
  a.command = command;
  a.result = result;
  return a;
}

}  // namespace kestrel::mavlink::testing
