#pragma once
// Message types used only by the framework's tests and benchmarks.
#include <cstdint>
#include <vector>

#include "kestrel/message.hpp"

namespace kestrel::test {

struct Number {
  std::int64_t index = 0;  ///< publication index at the source
  double value = 0.0;
};

/// A block of bytes that remembers where its buffer was made and when, so a sink can prove it
/// was never copied and measure how long it took to arrive.
struct Blob {
  std::vector<std::uint8_t> bytes;
  const void* origin = nullptr;  ///< bytes.data() at the source
  std::int64_t created_ns = 0;   ///< steady clock at publication
};

}  // namespace kestrel::test

KESTREL_MESSAGE(kestrel::test::Number, "test.Number", "a number with its source index");
KESTREL_MESSAGE(kestrel::test::Blob, "test.Blob", "an opaque block of bytes");
