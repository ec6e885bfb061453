// Fuzz target: what a live-view client sends as text (plugins/foxglove_bridge/protocol.hpp). Any
// bytes must parse into a request or give a ProtocolError that says why; never a crash, another
// exception or a leak. A subscribe's ids must be what the bytes hold: 32-bit.
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "protocol.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const auto request = kestrel::foxglove::parse_client_text(text);
    if (const auto* u = std::get_if<kestrel::foxglove::Unsupported>(&request); u && u->op.size() > size) std::abort();
  } catch (const kestrel::foxglove::ProtocolError&) {
    // not a foxglove.websocket.v1 request: the message says why
  }
  return 0;
}
