#include "crc32.hpp"

#include <zlib.h>

#include <algorithm>
#include <limits>

namespace kestrel::mcap {

std::uint32_t crc32(std::uint32_t crc, std::span<const std::uint8_t> bytes) {
  uLong value = crc;
  while (!bytes.empty()) {  // zlib takes uInt lengths
    const std::size_t n = std::min<std::size_t>(bytes.size(), std::numeric_limits<uInt>::max());
    value = ::crc32(value, bytes.data(), static_cast<uInt>(n));
    bytes = bytes.subspan(n);
  }
  return static_cast<std::uint32_t>(value);
}

}  // namespace kestrel::mcap
