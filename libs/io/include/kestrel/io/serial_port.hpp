#pragma once
// A serial port (termios) for drivers of devices on USB-serial or UART links: raw 8N1 at a chosen
// baud rate, reads that wait with a timeout, and a hang-up (the device unplugged) told apart from
// a quiet line. Tests drive it with a pseudo-terminal.
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include "kestrel/error.hpp"

namespace kestrel::io {

/// The port went away (unplugged, hung up) or was never there.
class PortLost : public Error {
 public:
  using Error::Error;
};

class SerialPort {
 public:
  /// The baud rates termios offers, from 9600 to 4000000.
  static bool supports_baud(int baud);

  /// Opens and configures `path`. Throws PortLost when it is not there, Error when it is not a
  /// terminal, access is denied or the baud rate is not one termios offers.
  SerialPort(std::string path, int baud);
  ~SerialPort();
  SerialPort(const SerialPort&) = delete;
  SerialPort& operator=(const SerialPort&) = delete;

  /// Reads what has arrived into `buffer`, waiting at most `timeout` for the first byte; 0 when
  /// nothing came. Throws PortLost on a hang-up.
  std::size_t read_some(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout);
  /// Writes all of `bytes`. Throws PortLost on a hang-up.
  void write(std::span<const std::uint8_t> bytes);
  const std::string& path() const { return path_; }
  int baud() const { return baud_; }

 private:
  std::string path_;
  int baud_ = 0;
  int fd_ = -1;
};

}  // namespace kestrel::io
