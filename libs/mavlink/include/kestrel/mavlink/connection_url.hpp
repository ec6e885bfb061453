#pragma once
// A link named as MAVSDK names it (src/core/cli_arg.cpp), the form drone users already know:
//   udpin://0.0.0.0:14540        listen on a UDP port; reply to whoever spoke last
//   udpout://127.0.0.1:14540     send to a UDP port; replies come back to the same socket
//   serial:///dev/ttyACM0:921600 a serial port at a baud rate (57600 when left out)
#include <cstdint>
#include <string>

namespace kestrel::mavlink {

struct ConnectionUrl {
  enum class Kind { udp_in, udp_out, serial };
  Kind kind = Kind::udp_in;
  std::string host;        ///< udp: the address to bind (udpin) or send to (udpout)
  std::uint16_t port = 0;  ///< udp
  std::string device;      ///< serial: the port's path
  int baud = 57600;        ///< serial
  std::string text;        ///< as written
};

/// Throws kestrel::Error saying what is wrong and showing the three forms.
ConnectionUrl parse_connection_url(const std::string& text);
/// Whether parse_connection_url takes it (for parameter rules, checked when a graph is validated).
bool valid_connection_url(const std::string& text);

}  // namespace kestrel::mavlink
