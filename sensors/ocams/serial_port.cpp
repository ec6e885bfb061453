#include "serial_port.hpp"

#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace kestrel::ocams {

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
    case 921600:
      return B921600;
    default:
      return 0;
  }
}

}  // namespace

SerialPort::SerialPort(std::string path, int baud) : path_(std::move(path)) {
  const speed_t speed = speed_of(baud);
  if (speed == 0) throw Error(path_ + ": " + std::to_string(baud) + " is not a baud rate termios offers");
  fd_ = ::open(path_.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd_ < 0) {
    const int e = errno;
    if (e == EACCES) throw Error(path_ + ": permission denied (docs/hardware.md: the udev rule, or the dialout group)");
    throw PortLost(path_ + ": " + std::strerror(e));
  }
  termios t{};
  if (tcgetattr(fd_, &t) != 0) {
    const int e = errno;
    ::close(fd_);
    throw Error(path_ + " is not a serial port: " + std::strerror(e));
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
    throw Error(path_ + ": cannot configure the port: " + std::strerror(e));
  }
  tcflush(fd_, TCIFLUSH);  // what the device said before we listened
}

SerialPort::~SerialPort() {
  if (fd_ >= 0) ::close(fd_);
}

std::optional<std::string> SerialPort::read_line(std::chrono::milliseconds timeout, std::size_t max_line) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    const std::size_t end = pending_.find('\n');
    if (end != std::string::npos || pending_.size() >= max_line) {
      const std::size_t cut = end != std::string::npos ? end : max_line;
      std::string line = pending_.substr(0, cut);
      pending_.erase(0, end != std::string::npos ? cut + 1 : cut);
      if (!line.empty() && line.back() == '\r') line.pop_back();
      return line;
    }
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now()).count();
    if (left < 0) return std::nullopt;
    pollfd p{fd_, POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(left));
    if (ready < 0) {
      if (errno == EINTR) continue;
      throw PortLost(path_ + ": " + std::strerror(errno));
    }
    if (ready == 0) return std::nullopt;
    char buffer[256];
    const ssize_t n = ::read(fd_, buffer, sizeof buffer);
    if (n > 0) {
      pending_.append(buffer, static_cast<std::size_t>(n));
      continue;
    }
    if (n < 0 && (errno == EAGAIN || errno == EINTR)) continue;
    // Nothing to read though poll said so, or an error: the other end hung up.
    if (p.revents & (POLLHUP | POLLERR) || n == 0 || n < 0)
      throw PortLost(path_ + ": the device hung up" + (n < 0 ? std::string(" (") + std::strerror(errno) + ")" : ""));
  }
}

void SerialPort::write(const std::string& text) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd_, text.data() + done, text.size() - done);
    if (n > 0) {
      done += static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && errno == EAGAIN) {
      pollfd p{fd_, POLLOUT, 0};
      ::poll(&p, 1, 100);
      continue;
    }
    throw PortLost(path_ + ": writing: " + std::strerror(errno));
  }
}

}  // namespace kestrel::ocams
