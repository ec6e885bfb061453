#pragma once
// Little-endian serialization as MCAP lays it out: fixed-width integers, uint32-prefixed strings
// and maps, uint64-prefixed byte arrays. The reader checks every length against what is left and
// throws FormatError instead of reading past the end.
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <string_view>

#include "kestrel/mcap/records.hpp"

namespace kestrel::mcap {

class ByteWriter {
 public:
  explicit ByteWriter(Bytes& out) : out_(out) {}

  void u8(std::uint8_t v) { out_.push_back(v); }
  void u16(std::uint16_t v) { little_endian(v, 2); }
  void u32(std::uint32_t v) { little_endian(v, 4); }
  void u64(std::uint64_t v) { little_endian(v, 8); }
  void raw(std::span<const std::uint8_t> bytes) { out_.insert(out_.end(), bytes.begin(), bytes.end()); }
  void raw(std::string_view text) { out_.insert(out_.end(), text.begin(), text.end()); }
  void string(std::string_view text) {
    u32(static_cast<std::uint32_t>(text.size()));
    raw(text);
  }
  void bytes_u32(std::span<const std::uint8_t> bytes) {
    u32(static_cast<std::uint32_t>(bytes.size()));
    raw(bytes);
  }
  void bytes_u64(std::span<const std::uint8_t> bytes) {
    u64(bytes.size());
    raw(bytes);
  }

  /// Starts a record: its opcode and a length to be patched by end_record.
  std::size_t begin_record(Opcode opcode) {
    u8(static_cast<std::uint8_t>(opcode));
    const std::size_t at = out_.size();
    u64(0);
    return at;
  }
  void end_record(std::size_t length_at) {
    const std::uint64_t length = out_.size() - length_at - 8;
    for (int i = 0; i < 8; ++i)
      out_[length_at + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(length >> (8 * i));
  }
  /// Starts a uint32 byte-length prefix (arrays, maps); end_prefix patches it.
  std::size_t begin_prefix() {
    const std::size_t at = out_.size();
    u32(0);
    return at;
  }
  void end_prefix(std::size_t at) {
    const auto length = static_cast<std::uint32_t>(out_.size() - at - 4);
    for (int i = 0; i < 4; ++i) out_[at + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(length >> (8 * i));
  }

  std::size_t size() const { return out_.size(); }

 private:
  void little_endian(std::uint64_t v, int bytes) {
    for (int i = 0; i < bytes; ++i) out_.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
  }
  Bytes& out_;
};

class ByteReader {
 public:
  /// `what` names the record in errors ("Channel record at byte 123").
  ByteReader(std::span<const std::uint8_t> data, std::string what) : data_(data), what_(std::move(what)) {}

  std::uint8_t u8() { return static_cast<std::uint8_t>(little_endian(1, "a uint8")); }
  std::uint16_t u16() { return static_cast<std::uint16_t>(little_endian(2, "a uint16")); }
  std::uint32_t u32() { return static_cast<std::uint32_t>(little_endian(4, "a uint32")); }
  std::uint64_t u64() { return little_endian(8, "a uint64"); }
  std::span<const std::uint8_t> take(std::uint64_t n, const char* field) {
    need(n, field);
    const auto out = data_.subspan(pos_, static_cast<std::size_t>(n));
    pos_ += static_cast<std::size_t>(n);
    return out;
  }
  std::string string(const char* field) {
    const auto bytes = take(u32(), field);
    return {bytes.begin(), bytes.end()};
  }
  Bytes bytes_u32(const char* field) {
    const auto bytes = take(u32(), field);
    return {bytes.begin(), bytes.end()};
  }
  Bytes bytes_u64(const char* field) {
    const auto bytes = take(u64(), field);
    return {bytes.begin(), bytes.end()};
  }
  /// A uint32-prefixed group (array, map) as a reader of its own.
  ByteReader group(const char* field) { return ByteReader(take(u32(), field), what_ + ", " + field); }

  /// The bytes read so far (for a CRC over a record's leading fields).
  std::span<const std::uint8_t> consumed() const { return data_.first(pos_); }
  std::size_t remaining() const { return data_.size() - pos_; }
  std::size_t position() const { return pos_; }
  bool done() const { return pos_ == data_.size(); }
  const std::string& what() const { return what_; }

 private:
  void need(std::uint64_t n, const char* field) const {
    if (n > data_.size() - pos_)
      throw FormatError(what_ + ": " + field + " needs " + std::to_string(n) + " bytes, " +
                        std::to_string(data_.size() - pos_) + " are left");
  }
  std::uint64_t little_endian(int bytes, const char* field) {
    need(static_cast<std::uint64_t>(bytes), field);
    std::uint64_t v = 0;
    for (int i = 0; i < bytes; ++i)
      v |= static_cast<std::uint64_t>(data_[pos_ + static_cast<std::size_t>(i)]) << (8 * i);
    pos_ += static_cast<std::size_t>(bytes);
    return v;
  }

  std::span<const std::uint8_t> data_;
  std::size_t pos_ = 0;
  std::string what_;
};

}  // namespace kestrel::mcap
