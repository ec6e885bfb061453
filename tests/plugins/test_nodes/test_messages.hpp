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

struct Blob {
  std::vector<std::uint8_t> bytes;
};

}  // namespace kestrel::test

KESTREL_MESSAGE(kestrel::test::Number, "test.Number", "a number with its source index");
KESTREL_MESSAGE(kestrel::test::Blob, "test.Blob", "an opaque block of bytes");
