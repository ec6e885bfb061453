// Fuzz target: the oCamS frame unpacker and the raw frame's clock. Any bytes, as a frame of any
// size the first two bytes pick, must unpack or give a kestrel::Error; never a crash or a read
// outside the bytes.
#include <cstdint>
#include <kestrel/error.hpp>

#include "raw_frame.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  const int width = 2 * (data[0] % 64), height = 2 * (data[1] % 48);
  const std::span<const std::uint8_t> raw(data + 2, size - 2);
  kestrel::ocams::device_clock_ms(raw);
  try {
    const auto pair = kestrel::ocams::unpack(raw, width, height);
    // What unpacks packs back to the same words, but for the pixels the clock overwrote.
    const auto again = kestrel::ocams::pack(pair.left, pair.right, pair.device_ms);
    if (again.size() != raw.size()) __builtin_trap();
  } catch (const kestrel::Error&) {
    // the wrong number of bytes for the size: the message says so
  }
  return 0;
}
