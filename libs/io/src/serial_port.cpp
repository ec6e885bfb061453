#include "kestrel/io/serial_port.hpp"

#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace kestrel::io {

namespace {

speed_t speed_of(int baud) {
  switch (baud) {
    case 9600:
      return B9600;
    case 19200:
      return B19200;
    case 38400:
      return B38400;
    case 57600:
      return B57600;
    case 115200:
      return B115200;
    case 230400:
      return B230400;
    case 460800:
      return B460800;
    case 500000:
      return B500000;
    case 921600:
      return B921600;
    case 1000000:
      return B1000000;
    case 1500000:
      return B1500000;
    case 2000000:
      return B2000000;
    case 3000000:
      return B3000000;
    case 4000000:
      return B4000000;
    default:
      return 0;
  }
}

std::string errno_text(int e) { return std::strerror(e); }

}  // namespace

bool SerialPort::supports_baud(int baud) { return speed_of(baud) != 0; }

SerialPort::SerialPort(std::string path, int baud) : path_(std::move(path)), baud_(baud) {
  const speed_t speed = speed_of(baud);
  if (speed == 0) throw Error(path_ + ": " + std::to_string(baud) + " is not a baud rate termios offers");
  fd_ = ::open(path_.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd_ < 0) {
    const int e = errno;
    if (e == EACCES) throw Error(path_ + ": permission denied (the udev rule, or the dialout group)");
    throw PortLost(path_ + ": " + errno_text(e));
  }
  termios t{};
  if (tcgetattr(fd_, &t) != 0) {
    const int e = errno;
    ::close(fd_);
    throw Error(path_ + " is not a serial port: " + errno_text(e));
  }
  cfmakeraw(&t);
  t.c_cflag |= CLOCAL | CREAD;
  t.c_cflag &= ~static_cast<tcflag_t>(CSTOPB | CRTSCTS);
  cfsetispeed(&t, speed);
  cfsetospeed(&t, speed);
  t.c_cc[VMIN] = 0;
  t.c_cc[VTIME] = 0;
  if (tcsetattr(fd_, TCSANOW, &t) != 0) {
    const int e = errno;
    ::close(fd_);
    throw Error(path_ + ": cannot configure the port: " + errno_text(e));
  }
  tcflush(fd_, TCIFLUSH);  // what the device said before we listened
}

SerialPort::~SerialPort() {
  if (fd_ >= 0) ::close(fd_);
}

std::size_t SerialPort::read_some(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now()).count();
    pollfd p{fd_, POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(std::max<long long>(left, 0)));
    if (ready < 0) {
      if (errno == EINTR) continue;
      throw PortLost(path_ + ": " + errno_text(errno));
    }
    if (ready == 0) return 0;
    const ssize_t n = ::read(fd_, buffer.data(), buffer.size());
    if (n > 0) return static_cast<std::size_t>(n);
    if (n < 0 && (errno == EAGAIN || errno == EINTR)) {
      if (left <= 0) return 0;
      continue;
    }
    // Nothing to read though poll said so, or an error: the other end hung up.
    throw PortLost(path_ + ": the device hung up" + (n < 0 ? " (" + errno_text(errno) + ")" : std::string()));
  }
}

void SerialPort::write(std::span<const std::uint8_t> bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd_, bytes.data() + done, bytes.size() - done);
    if (n > 0) {
      done += static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && (errno == EAGAIN || errno == EINTR)) {
      pollfd p{fd_, POLLOUT, 0};
      ::poll(&p, 1, 100);
      continue;
    }
    throw PortLost(path_ + ": writing: " + errno_text(errno));
  }
}

}  // namespace kestrel::io
