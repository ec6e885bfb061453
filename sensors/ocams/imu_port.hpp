#pragma once
// ImuPort: the IMU's serial port read as lines, on kestrel's serial port (raw 8N1, reads with a timeout, a
// hang-up told apart from a quiet line). The oCamS's IMU is a CDC-ACM port; tests use a
// pseudo-terminal.
#include <chrono>
#include <kestrel/io/serial_port.hpp>
#include <optional>
#include <string>

namespace kestrel::ocams {

/// The port went away (unplugged, hung up).
using PortLost = io::PortLost;

class ImuPort {
 public:
  /// Opens and configures `path`. Throws PortLost when it is not there, Error when it is not a
  /// terminal or refuses the baud rate.
  ImuPort(std::string path, int baud) : port_(std::move(path), baud) {}

  /// The next line without its CR LF, waiting at most `timeout`; nullopt if none is complete by
  /// then. A line longer than `max_line` bytes is cut and returned as it is (the parser refuses
  /// it). Throws PortLost on a hang-up.
  std::optional<std::string> read_line(std::chrono::milliseconds timeout, std::size_t max_line = 512);
  /// Writes all of `text`. Throws PortLost on a hang-up.
  void write(const std::string& text);
  const std::string& path() const { return port_.path(); }

 private:
  io::SerialPort port_;
  std::string pending_;
};

}  // namespace kestrel::ocams
