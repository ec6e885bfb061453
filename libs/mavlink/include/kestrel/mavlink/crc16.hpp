#pragma once
// MAVLink's checksum: CRC-16/MCRF4XX (the "X.25 accumulate" of the MAVLink C library), initial
// value 0xFFFF, no final XOR. The check value of ASCII "123456789" is 0x6F91.
#include <cstdint>
#include <span>
#include <string_view>

namespace kestrel::mavlink {

inline constexpr std::uint16_t crc16_initial = 0xFFFF;

constexpr std::uint16_t crc16_accumulate(std::uint8_t byte, std::uint16_t crc) {
  std::uint8_t t = static_cast<std::uint8_t>(byte ^ (crc & 0xFF));
  t = static_cast<std::uint8_t>(t ^ (t << 4));
  return static_cast<std::uint16_t>((crc >> 8) ^ (t << 8) ^ (t << 3) ^ (t >> 4));
}

constexpr std::uint16_t crc16_accumulate(std::span<const std::uint8_t> bytes, std::uint16_t crc) {
  for (const std::uint8_t b : bytes) crc = crc16_accumulate(b, crc);
  return crc;
}

constexpr std::uint16_t crc16_accumulate(std::string_view text, std::uint16_t crc) {
  for (const char c : text) crc = crc16_accumulate(static_cast<std::uint8_t>(c), crc);
  return crc;
}

}  // namespace kestrel::mavlink
