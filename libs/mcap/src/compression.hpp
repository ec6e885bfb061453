#pragma once
// Chunk compression: "" (none), "zstd" (libzstd) and "lz4" (the LZ4 frame format, liblz4), the
// formats the MCAP specification names.
#include <span>
#include <string>
#include <string_view>

#include "kestrel/mcap/records.hpp"

namespace kestrel::mcap {

/// True for "", "zstd" and "lz4".
bool is_supported_compression(std::string_view compression);

/// `level` 0 takes the library's default. Throws Error for an unknown compression.
Bytes compress(std::string_view compression, std::span<const std::uint8_t> data, int level = 0);

/// Throws FormatError when `data` does not decompress to exactly `uncompressed_size` bytes. Allocates
/// `uncompressed_size` bytes: the caller bounds it (Reader's `max_chunk_bytes`).
Bytes decompress(std::string_view compression, std::span<const std::uint8_t> data, std::uint64_t uncompressed_size);

}  // namespace kestrel::mcap
