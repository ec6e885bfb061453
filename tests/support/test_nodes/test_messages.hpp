#pragma once
// Message types used only by the framework's tests and benchmarks.
#include <atomic>
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

/// A message that counts every copy made of it, in the whole test plugin, so a test can prove
/// that messages travel between nodes without being copied.
struct Counted {
  std::int64_t index = 0;

  Counted() = default;
  explicit Counted(std::int64_t i) : index(i) {}
  Counted(const Counted& other) : index(other.index) { copies().fetch_add(1); }
  Counted& operator=(const Counted& other) {
    index = other.index;
    copies().fetch_add(1);
    return *this;
  }
  Counted(Counted&&) = default;
  Counted& operator=(Counted&&) = default;
  ~Counted() = default;

  static std::atomic<std::uint64_t>& copies() {
    static std::atomic<std::uint64_t> count{0};
    return count;
  }
};

}  // namespace kestrel::test

KESTREL_MESSAGE(kestrel::test::Counted, "test.Counted", "an index; counts the copies made of it");
KESTREL_MESSAGE(kestrel::test::Number, "test.Number", "a number with its source index");
KESTREL_MESSAGE_FIELDS(kestrel::test::Number, {"index", "int64", "", "", "publication index at the source"},
                       {"value", "double", "m", "world", "the number"});
KESTREL_MESSAGE(kestrel::test::Blob, "test.Blob", "an opaque block of bytes");
