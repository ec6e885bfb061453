#include "kestrel/mavlink/connection_url.hpp"

#include <charconv>
#include <kestrel/error.hpp>
#include <kestrel/io/serial_port.hpp>

namespace kestrel::mavlink {

namespace {

constexpr const char* forms = "udpin://HOST:PORT, udpout://HOST:PORT or serial:///dev/PORT[:BAUD]";

[[noreturn]] void refuse(const std::string& text, const std::string& why) {
  throw Error("connection '" + text + "': " + why + " (expected " + forms + ")");
}

template <class T>
bool parse_number(const std::string& s, T& out) {
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && end == s.data() + s.size() && !s.empty();
}

}  // namespace

ConnectionUrl parse_connection_url(const std::string& text) {
  ConnectionUrl url;
  url.text = text;
  const auto scheme_end = text.find("://");
  if (scheme_end == std::string::npos) refuse(text, "no scheme");
  const std::string scheme = text.substr(0, scheme_end);
  const std::string rest = text.substr(scheme_end + 3);
  if (scheme == "serial") {
    url.kind = ConnectionUrl::Kind::serial;
    const auto colon = rest.rfind(':');
    url.device = colon == std::string::npos ? rest : rest.substr(0, colon);
    if (colon != std::string::npos && !parse_number(rest.substr(colon + 1), url.baud))
      refuse(text, "'" + rest.substr(colon + 1) + "' is not a baud rate");
    if (url.device.empty() || url.device.front() != '/')
      refuse(text, "the serial port must be a path such as /dev/ttyACM0");
    if (!io::SerialPort::supports_baud(url.baud))
      refuse(text, std::to_string(url.baud) + " is not a baud rate termios offers");
    return url;
  }
  if (scheme == "udpin" || scheme == "udp")
    url.kind = ConnectionUrl::Kind::udp_in;
  else if (scheme == "udpout")
    url.kind = ConnectionUrl::Kind::udp_out;
  else
    refuse(text, "unknown scheme '" + scheme + "'");
  const auto colon = rest.rfind(':');
  if (colon == std::string::npos) refuse(text, "no port");
  url.host = rest.substr(0, colon);
  if (url.host.empty()) url.host = url.kind == ConnectionUrl::Kind::udp_in ? "0.0.0.0" : "";
  if (url.host.empty()) refuse(text, "udpout needs the host to send to");
  unsigned port = 0;
  if (!parse_number(rest.substr(colon + 1), port) || port == 0 || port > 65535)
    refuse(text, "'" + rest.substr(colon + 1) + "' is not a port (1..65535)");
  url.port = static_cast<std::uint16_t>(port);
  return url;
}

bool valid_connection_url(const std::string& text) {
  try {
    parse_connection_url(text);
    return true;
  } catch (const Error&) {
    return false;
  }
}

}  // namespace kestrel::mavlink
