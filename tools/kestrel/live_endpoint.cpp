#include "live_endpoint.hpp"

#include <charconv>

namespace kestrel::cli {

std::optional<LiveEndpoint> parse_live_endpoint(std::string_view text) {
  LiveEndpoint endpoint;
  std::string_view port = text;
  if (const auto colon = text.rfind(':'); colon != std::string_view::npos) {
    std::string_view address = text.substr(0, colon);
    if (address.size() >= 2 && address.front() == '[' && address.back() == ']')
      address = address.substr(1, address.size() - 2);
    if (address.empty()) return std::nullopt;
    endpoint.address = std::string(address);
    port = text.substr(colon + 1);
  }
  const auto [end, ec] = std::from_chars(port.data(), port.data() + port.size(), endpoint.port);
  if (port.empty() || ec != std::errc() || end != port.data() + port.size() || endpoint.port < 0 ||
      endpoint.port > 65535)
    return std::nullopt;
  return endpoint;
}

}  // namespace kestrel::cli
