#pragma once
// The CDR encoding ROS 2 messages travel in (MCAP message encoding `cdr`): little-endian, a
// 4-byte encapsulation header (0x00 0x01 0x00 0x00, CDR_LE), each primitive aligned to its own
// size counted from the end of that header, strings as a uint32 length that counts a trailing
// NUL, sequences as a uint32 count and then their elements.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "kestrel/error.hpp"

namespace kestrel::ros2 {

/// Bytes that are not the CDR a schema says: the message says what and at which offset.
class CdrError : public Error {
 public:
  using Error::Error;
};

class CdrWriter {
 public:
  CdrWriter();  ///< starts with the CDR_LE encapsulation header

  void boolean(bool v) { u8(v ? 1 : 0); }
  void u8(std::uint8_t v) { bytes_.push_back(v); }
  void i8(std::int8_t v) { u8(static_cast<std::uint8_t>(v)); }
  void u16(std::uint16_t v) { primitive(v, 2); }
  void i16(std::int16_t v) { primitive(static_cast<std::uint16_t>(v), 2); }
  void u32(std::uint32_t v) { primitive(v, 4); }
  void i32(std::int32_t v) { primitive(static_cast<std::uint32_t>(v), 4); }
  void u64(std::uint64_t v) { primitive(v, 8); }
  void i64(std::int64_t v) { primitive(static_cast<std::uint64_t>(v), 8); }
  void f32(float v);
  void f64(double v);
  void string(std::string_view v);
  /// The count before a sequence's elements.
  void sequence_length(std::size_t n);
  /// A uint8[] (or byte[]) sequence: count and bytes.
  void bytes(std::span<const std::uint8_t> v);

  const std::vector<std::uint8_t>& data() const { return bytes_; }
  std::vector<std::uint8_t> take() { return std::move(bytes_); }

 private:
  void align(std::size_t n);
  void primitive(std::uint64_t v, std::size_t size);
  std::vector<std::uint8_t> bytes_;
};

class CdrReader {
 public:
  /// Checks the encapsulation header: CDR_LE only (ROS 2's default); throws CdrError otherwise.
  explicit CdrReader(std::span<const std::uint8_t> data);

  bool boolean() { return u8() != 0; }
  std::uint8_t u8();
  std::int8_t i8() { return static_cast<std::int8_t>(u8()); }
  std::uint16_t u16() { return static_cast<std::uint16_t>(primitive(2)); }
  std::int16_t i16() { return static_cast<std::int16_t>(primitive(2)); }
  std::uint32_t u32() { return static_cast<std::uint32_t>(primitive(4)); }
  std::int32_t i32() { return static_cast<std::int32_t>(primitive(4)); }
  std::uint64_t u64() { return primitive(8); }
  std::int64_t i64() { return static_cast<std::int64_t>(primitive(8)); }
  float f32();
  double f64();
  std::string string();
  /// A sequence's count, checked against the bytes left: each element takes at least
  /// `min_element_bytes`.
  std::uint32_t sequence_length(std::size_t min_element_bytes = 1);
  std::vector<std::uint8_t> bytes();

  std::size_t remaining() const { return data_.size() - pos_; }
  std::size_t offset() const { return pos_; }  ///< from the start of the encapsulation header

 private:
  void align(std::size_t n);
  void need(std::size_t n, const char* what) const;
  std::uint64_t primitive(std::size_t size);
  std::span<const std::uint8_t> data_;
  std::size_t pos_ = 4;
};

}  // namespace kestrel::ros2
