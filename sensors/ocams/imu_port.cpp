#include "imu_port.hpp"

#include <array>
#include <cstdint>

namespace kestrel::ocams {

std::optional<std::string> ImuPort::read_line(std::chrono::milliseconds timeout, std::size_t max_line) {
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
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() < 0) return std::nullopt;
    std::array<std::uint8_t, 256> buffer;
    const std::size_t n = port_.read_some(buffer, left);
    if (n == 0) return std::nullopt;
    pending_.append(reinterpret_cast<const char*>(buffer.data()), n);
  }
}

void ImuPort::write(const std::string& text) {
  port_.write(std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
}

}  // namespace kestrel::ocams
