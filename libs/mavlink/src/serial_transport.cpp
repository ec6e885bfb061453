// MAVLink over a serial port (a telemetry radio, or the autopilot's TELEM port on a UART or USB).
#include <kestrel/io/serial_port.hpp>

#include "kestrel/mavlink/transport.hpp"
#include "kestrel/mavlink/udp_transport.hpp"

namespace kestrel::mavlink {

namespace {

class SerialTransport : public Transport {
 public:
  explicit SerialTransport(const ConnectionUrl& url) : port_(url.device, url.baud) {}
  bool send(std::span<const std::uint8_t> bytes) override {
    port_.write(bytes);
    return true;
  }
  std::size_t receive(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout) override {
    return port_.read_some(buffer, timeout);
  }
  std::string describe() const override { return "serial " + port_.path() + " at " + std::to_string(port_.baud()); }

 private:
  io::SerialPort port_;
};

}  // namespace

std::unique_ptr<Transport> open_transport(const ConnectionUrl& url) {
  if (url.kind == ConnectionUrl::Kind::serial) return std::make_unique<SerialTransport>(url);
  return std::make_unique<UdpTransport>(url);
}

}  // namespace kestrel::mavlink
