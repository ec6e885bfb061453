#pragma once
// CRC-32 (ISO-HDLC, as zlib computes it), the checksum MCAP uses everywhere.
#include <cstdint>
#include <span>

namespace kestrel::mcap {

/// Continues `crc` (0 to start) over `bytes`.
std::uint32_t crc32(std::uint32_t crc, std::span<const std::uint8_t> bytes);

}  // namespace kestrel::mcap
