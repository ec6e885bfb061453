#include "compression.hpp"

#include <lz4frame.h>
#include <zstd.h>

#include <memory>

namespace kestrel::mcap {

bool is_supported_compression(std::string_view c) { return c.empty() || c == "zstd" || c == "lz4"; }

Bytes compress(std::string_view compression, std::span<const std::uint8_t> data, int level) {
  if (compression.empty()) return {data.begin(), data.end()};
  if (compression == "zstd") {
    Bytes out(ZSTD_compressBound(data.size()));
    const std::size_t n =
        ZSTD_compress(out.data(), out.size(), data.data(), data.size(), level == 0 ? ZSTD_CLEVEL_DEFAULT : level);
    if (ZSTD_isError(n)) throw Error(std::string("zstd compression failed: ") + ZSTD_getErrorName(n));
    out.resize(n);
    return out;
  }
  if (compression == "lz4") {
    LZ4F_preferences_t preferences{};
    preferences.compressionLevel = level;
    preferences.frameInfo.contentSize = data.size();  // lets readers size their buffer
    Bytes out(LZ4F_compressFrameBound(data.size(), &preferences));
    const std::size_t n = LZ4F_compressFrame(out.data(), out.size(), data.data(), data.size(), &preferences);
    if (LZ4F_isError(n)) throw Error(std::string("lz4 compression failed: ") + LZ4F_getErrorName(n));
    out.resize(n);
    return out;
  }
  throw Error("unknown chunk compression '" + std::string(compression) + "' (known: none, zstd, lz4)");
}

Bytes decompress(std::string_view compression, std::span<const std::uint8_t> data, std::uint64_t uncompressed_size) {
  const auto wrong_size = [&](std::uint64_t got) {
    return FormatError(std::string(compression) + " chunk decompressed to " + std::to_string(got) +
                       " bytes, its record says " + std::to_string(uncompressed_size));
  };
  if (compression.empty()) {
    if (data.size() != uncompressed_size) throw wrong_size(data.size());
    return {data.begin(), data.end()};
  }
  Bytes out(static_cast<std::size_t>(uncompressed_size));
  if (compression == "zstd") {
    const std::size_t n = ZSTD_decompress(out.data(), out.size(), data.data(), data.size());
    if (ZSTD_isError(n)) throw FormatError(std::string("zstd chunk does not decompress: ") + ZSTD_getErrorName(n));
    if (n != uncompressed_size) throw wrong_size(n);
    return out;
  }
  if (compression == "lz4") {
    LZ4F_dctx* raw = nullptr;
    if (LZ4F_isError(LZ4F_createDecompressionContext(&raw, LZ4F_VERSION))) throw Error("lz4: out of memory");
    const std::unique_ptr<LZ4F_dctx, decltype(&LZ4F_freeDecompressionContext)> context(raw,
                                                                                       &LZ4F_freeDecompressionContext);
    std::size_t written = 0, read = 0;
    while (read < data.size()) {
      std::size_t out_size = out.size() - written, in_size = data.size() - read;
      const std::size_t hint =
          LZ4F_decompress(context.get(), out.data() + written, &out_size, data.data() + read, &in_size, nullptr);
      if (LZ4F_isError(hint))
        throw FormatError(std::string("lz4 chunk does not decompress: ") + LZ4F_getErrorName(hint));
      written += out_size;
      read += in_size;
      if (hint == 0) break;                                          // end of the frame
      if (in_size == 0 && out_size == 0) throw wrong_size(written);  // no progress: more output than the size
    }
    if (written != uncompressed_size) throw wrong_size(written);
    return out;
  }
  throw FormatError("unknown chunk compression '" + std::string(compression) + "' (known: none, zstd, lz4)");
}

}  // namespace kestrel::mcap
