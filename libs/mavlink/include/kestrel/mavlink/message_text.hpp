#pragma once
// A received message as one line of text, its name and then each field in XML order
// (`HEARTBEAT type=2 autopilot=12 ...`), read from the payload through its definition, so that any
// message kestrel knows prints without code of its own (`kestrel mavlink listen`).
#include <span>
#include <string>

#include "kestrel/mavlink/message_definition.hpp"

namespace kestrel::mavlink {

std::string message_text(const MessageDefinition& definition, std::span<const std::uint8_t> payload);

}  // namespace kestrel::mavlink
