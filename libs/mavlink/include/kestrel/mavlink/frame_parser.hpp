#pragma once
// Frames out of a byte stream (a serial line, or UDP datagrams one after another). It finds each
// magic byte, waits for the whole frame, checks it, and on a bad checksum resumes one byte after
// that magic, so that garbage costs only itself. A frame of an id it does not know cannot be
// checked (its CRC_EXTRA is unknown): it is counted and stepped over by its length, unless a frame
// that does check out starts inside it, in which case it was noise posing as a header and the real
// frame is kept. It never reads past what it holds.
#include <cstdint>
#include <span>
#include <vector>

#include "kestrel/mavlink/frame.hpp"

namespace kestrel::mavlink {

struct ParserCounts {
  std::uint64_t frames = 0;         ///< good frames delivered
  std::uint64_t v1_frames = 0;      ///< of which MAVLink 1
  std::uint64_t signed_frames = 0;  ///< of which signed (checked by signing.hpp, not here)
  std::uint64_t bad_checksum = 0;   ///< a known id whose checksum did not match
  std::uint64_t unknown_id = 0;     ///< well-formed frames of an id kestrel does not know
  std::uint64_t bad_flags = 0;      ///< incompatibility flags kestrel does not understand
  std::uint64_t bytes_skipped = 0;  ///< bytes that belonged to no frame
};

class FrameParser {
 public:
  using Lookup = const MessageDefinition* (*)(std::uint32_t id);
  /// `lookup` gives the definitions of the ids to accept (default: messages.hpp's).
  explicit FrameParser(Lookup lookup = nullptr);

  /// Takes more bytes; returns the frames they complete, in order.
  std::vector<Frame> feed(std::span<const std::uint8_t> bytes);
  const ParserCounts& counts() const { return counts_; }
  /// Bytes held for a frame not yet complete.
  std::size_t pending() const { return buffer_.size(); }

 private:
  Lookup lookup_;
  std::vector<std::uint8_t> buffer_;
  ParserCounts counts_;
};

}  // namespace kestrel::mavlink
