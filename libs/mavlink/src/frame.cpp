#include "kestrel/mavlink/frame.hpp"

#include <algorithm>
#include <array>
#include <kestrel/error.hpp>
#include <string>

#include "kestrel/mavlink/crc16.hpp"
#include "kestrel/mavlink/signing.hpp"

namespace kestrel::mavlink {

std::uint16_t frame_checksum(std::span<const std::uint8_t> header_and_payload, std::uint8_t crc_extra) {
  return crc16_accumulate(crc_extra, crc16_accumulate(header_and_payload, crc16_initial));
}

namespace {

void append_checksum(std::vector<std::uint8_t>& frame, std::uint8_t crc_extra) {
  const std::uint16_t crc = frame_checksum(std::span(frame).subspan(1), crc_extra);
  frame.push_back(static_cast<std::uint8_t>(crc & 0xFF));
  frame.push_back(static_cast<std::uint8_t>(crc >> 8));
}

// Header, then payload, with room for the checksum.
template <std::size_t N>
std::vector<std::uint8_t> assemble(const std::array<std::uint8_t, N>& header, std::span<const std::uint8_t> payload) {
  std::vector<std::uint8_t> frame(N + payload.size());
  std::copy(header.begin(), header.end(), frame.begin());
  std::copy(payload.begin(), payload.end(), frame.begin() + static_cast<std::ptrdiff_t>(N));
  frame.reserve(frame.size() + checksum_size);
  return frame;
}

}  // namespace

std::vector<std::uint8_t> encode_v2(const MessageDefinition& definition, const void* message, Sender from,
                                    std::uint8_t sequence, std::uint8_t incompat_flags) {
  const std::vector<std::uint8_t> payload = definition.write(message);
  std::size_t length = payload.size();
  while (length > 1 && payload[length - 1] == 0) --length;
  const std::uint32_t id = definition.id();
  const std::array<std::uint8_t, header_v2> header = {magic_v2,
                                                      static_cast<std::uint8_t>(length),
                                                      incompat_flags,
                                                      0,
                                                      sequence,
                                                      from.system_id,
                                                      from.component_id,
                                                      static_cast<std::uint8_t>(id & 0xFF),
                                                      static_cast<std::uint8_t>((id >> 8) & 0xFF),
                                                      static_cast<std::uint8_t>((id >> 16) & 0xFF)};
  std::vector<std::uint8_t> frame = assemble(header, std::span(payload).first(length));
  append_checksum(frame, definition.crc_extra());
  return frame;
}

std::vector<std::uint8_t> encode_v1(const MessageDefinition& definition, const void* message, Sender from,
                                    std::uint8_t sequence) {
  if (definition.id() > 255)
    throw Error("MAVLink 1 cannot carry " + std::string(definition.name()) + " (id " + std::to_string(definition.id()) +
                " > 255)");
  const std::vector<std::uint8_t> payload = definition.write(message);
  const std::size_t length = definition.min_length();
  const std::array<std::uint8_t, header_v1> header = {magic_v1,          static_cast<std::uint8_t>(length),
                                                      sequence,          from.system_id,
                                                      from.component_id, static_cast<std::uint8_t>(definition.id())};
  std::vector<std::uint8_t> frame = assemble(header, std::span(payload).first(length));
  append_checksum(frame, definition.crc_extra());
  return frame;
}

std::vector<std::uint8_t> FrameWriter::encode(const MessageDefinition& definition, const void* message) {
  if (signing_) return signing_->encode(definition, message, from_, sequence_++);
  return encode_v2(definition, message, from_, sequence_++);
}

}  // namespace kestrel::mavlink
