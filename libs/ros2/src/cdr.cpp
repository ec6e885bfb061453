#include "kestrel/ros2/cdr.hpp"

#include <bit>
#include <cstring>

namespace kestrel::ros2 {

namespace {
constexpr std::size_t kHeader = 4;  // alignment counts from the end of the encapsulation header
}

CdrWriter::CdrWriter() : bytes_{0x00, 0x01, 0x00, 0x00} {}

void CdrWriter::align(std::size_t n) {
  while ((bytes_.size() - kHeader) % n != 0) bytes_.push_back(0);
}

void CdrWriter::primitive(std::uint64_t v, std::size_t size) {
  align(size);
  for (std::size_t i = 0; i < size; ++i) bytes_.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}

void CdrWriter::f32(float v) { primitive(std::bit_cast<std::uint32_t>(v), 4); }
void CdrWriter::f64(double v) { primitive(std::bit_cast<std::uint64_t>(v), 8); }

void CdrWriter::string(std::string_view v) {
  u32(static_cast<std::uint32_t>(v.size() + 1));
  bytes_.insert(bytes_.end(), v.begin(), v.end());
  bytes_.push_back(0);
}

void CdrWriter::sequence_length(std::size_t n) { u32(static_cast<std::uint32_t>(n)); }

void CdrWriter::bytes(std::span<const std::uint8_t> v) {
  sequence_length(v.size());
  bytes_.insert(bytes_.end(), v.begin(), v.end());
}

CdrReader::CdrReader(std::span<const std::uint8_t> data) : data_(data) {
  if (data.size() < kHeader) throw CdrError("CDR message of " + std::to_string(data.size()) + " bytes: no header");
  if (data[0] != 0x00 || data[1] != 0x01)
    throw CdrError("CDR encapsulation " + std::to_string(data[0]) + "," + std::to_string(data[1]) +
                   " is not CDR_LE (0,1), the only one ROS 2 writes by default");
}

void CdrReader::need(std::size_t n, const char* what) const {
  if (n > data_.size() - pos_)
    throw CdrError(std::string("CDR message ends at byte ") + std::to_string(data_.size()) + " inside " + what +
                   " at byte " + std::to_string(pos_));
}

void CdrReader::align(std::size_t n) {
  const std::size_t padding = (n - (pos_ - kHeader) % n) % n;
  need(padding, "padding");
  pos_ += padding;
}

std::uint64_t CdrReader::primitive(std::size_t size) {
  align(size);
  need(size, "a number");
  std::uint64_t v = 0;
  for (std::size_t i = 0; i < size; ++i) v |= static_cast<std::uint64_t>(data_[pos_ + i]) << (8 * i);
  pos_ += size;
  return v;
}

std::uint8_t CdrReader::u8() {
  need(1, "a byte");
  return data_[pos_++];
}

float CdrReader::f32() { return std::bit_cast<float>(static_cast<std::uint32_t>(primitive(4))); }
double CdrReader::f64() { return std::bit_cast<double>(primitive(8)); }

std::string CdrReader::string() {
  const std::uint32_t n = u32();
  need(n, "a string");
  if (n == 0) return {};  // some writers omit the NUL of an empty string
  std::string out(reinterpret_cast<const char*>(data_.data() + pos_), n - 1);
  if (data_[pos_ + n - 1] != 0) throw CdrError("CDR string at byte " + std::to_string(pos_) + " lacks its NUL");
  pos_ += n;
  return out;
}

std::uint32_t CdrReader::sequence_length(std::size_t min_element_bytes) {
  const std::uint32_t n = u32();
  if (min_element_bytes > 0 && n > remaining() / min_element_bytes)
    throw CdrError("CDR sequence at byte " + std::to_string(pos_) + " of " + std::to_string(n) +
                   " elements is longer than the " + std::to_string(remaining()) + " bytes left");
  return n;
}

std::vector<std::uint8_t> CdrReader::bytes() {
  const std::uint32_t n = sequence_length(1);
  std::vector<std::uint8_t> out(data_.begin() + static_cast<std::ptrdiff_t>(pos_),
                                data_.begin() + static_cast<std::ptrdiff_t>(pos_ + n));
  pos_ += n;
  return out;
}

}  // namespace kestrel::ros2
