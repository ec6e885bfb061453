#pragma once
// Loopback UDP for MAVLink tests: a socket listening on a port the system picked, or just such a
// port, free when asked.
#include <memory>

#include "kestrel/mavlink/udp_transport.hpp"

namespace kestrel::testing {

inline std::unique_ptr<mavlink::UdpTransport> listening_udp() {
  mavlink::ConnectionUrl url;
  url.kind = mavlink::ConnectionUrl::Kind::udp_in;
  url.host = "127.0.0.1";
  url.text = "udpin://127.0.0.1:0";
  return std::make_unique<mavlink::UdpTransport>(url);
}

inline std::uint16_t free_udp_port() { return listening_udp()->local_port(); }

}  // namespace kestrel::testing
