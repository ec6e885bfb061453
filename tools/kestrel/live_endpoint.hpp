#pragma once
// What `kestrel run --live` listens on: PORT alone is this machine only (127.0.0.1), so that a
// run never shows its camera and tracks to the network unless asked; ADDRESS:PORT (0.0.0.0:8765,
// [::]:8765) opens it, and the bridge warns.
#include <optional>
#include <string>
#include <string_view>

namespace kestrel::cli {

struct LiveEndpoint {
  std::string address = "127.0.0.1";
  int port = 0;
};

/// PORT or ADDRESS:PORT (an IPv6 address in brackets); none when it is neither.
std::optional<LiveEndpoint> parse_live_endpoint(std::string_view text);

}  // namespace kestrel::cli
