#pragma once
// MAVLink frames (the serialization chapter of the MAVLink guide). Version 2: magic 0xFD, length,
// incompatibility and compatibility flags, sequence, system and component ids, a 24-bit message
// id, the payload with its trailing zeros cut, CRC-16/MCRF4XX seeded with the message's CRC_EXTRA,
// and a 13-byte signature when incompatibility flag 0x01 is set. Version 1 (0xFE) has a 6-byte
// header and an 8-bit id; kestrel reads it, and writes it only for tests of peers that need it.
#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "kestrel/mavlink/message_definition.hpp"

namespace kestrel::mavlink {

inline constexpr std::uint8_t magic_v2 = 0xFD;
inline constexpr std::uint8_t magic_v1 = 0xFE;
inline constexpr std::uint8_t incompat_signed = 0x01;
inline constexpr std::size_t header_v2 = 10, header_v1 = 6, checksum_size = 2, signature_size = 13;
inline constexpr std::size_t max_frame_size = header_v2 + 255 + checksum_size + signature_size;

struct Frame {
  std::uint8_t version = 2;
  std::uint8_t incompat_flags = 0;
  std::uint8_t compat_flags = 0;
  std::uint8_t sequence = 0;
  std::uint8_t system_id = 0;
  std::uint8_t component_id = 0;
  std::uint32_t message_id = 0;
  std::vector<std::uint8_t> payload;  ///< as received: a version 2 payload may be cut short
  std::uint16_t checksum = 0;         ///< as received
  /// A signed frame's last 13 bytes: link id, 48-bit timestamp, 48-bit signature (signing.hpp).
  std::array<std::uint8_t, signature_size> signature{};

  bool is_signed() const { return (incompat_flags & incompat_signed) != 0; }
  std::uint8_t link_id() const { return signature[0]; }
  /// The signature's timestamp: 10 us units since 2015-01-01 UTC.
  std::uint64_t signature_timestamp() const {
    std::uint64_t t = 0;
    for (int i = 6; i >= 1; --i) t = (t << 8) | signature[static_cast<std::size_t>(i)];
    return t;
  }
  template <class M>
  bool is() const {
    return message_id == M::definition().id();
  }
  /// The message; fields past a cut payload read as zero.
  template <class M>
  M as() const {
    M m;
    M::definition().read(&m, payload);
    return m;
  }
};

/// Who sends: a system id (1..255) and a component id (MAV_COMPONENT).
struct Sender {
  std::uint8_t system_id = 1;
  std::uint8_t component_id = 0;
};

/// A version 2 frame of `message` (a struct of `definition`), its trailing zeros cut (one byte
/// always stays).
/// `incompat_flags` incompat_signed leaves the frame ready for its signature (append_signature in
/// signing.hpp), which covers the flags.
std::vector<std::uint8_t> encode_v2(const MessageDefinition& definition, const void* message, Sender from,
                                    std::uint8_t sequence, std::uint8_t incompat_flags = 0);
/// A version 1 frame: the base fields only, never cut. Throws Error for an id above 255.
std::vector<std::uint8_t> encode_v1(const MessageDefinition& definition, const void* message, Sender from,
                                    std::uint8_t sequence);

/// The checksum of a frame's bytes after the magic (header and payload), seeded with CRC_EXTRA.
std::uint16_t frame_checksum(std::span<const std::uint8_t> header_and_payload, std::uint8_t crc_extra);

class Signing;

/// A sender's frames, numbered in sequence (the sequence wraps at 256), and signed when it is
/// given a signing state (signing.hpp).
class FrameWriter {
 public:
  explicit FrameWriter(Sender from, std::shared_ptr<Signing> signing = nullptr)
      : from_(from), signing_(std::move(signing)) {}
  template <class M>
  std::vector<std::uint8_t> encode(const M& message) {
    return encode(M::definition(), &message);
  }
  std::vector<std::uint8_t> encode(const MessageDefinition& definition, const void* message);
  Sender sender() const { return from_; }

 private:
  Sender from_;
  std::shared_ptr<Signing> signing_;
  std::uint8_t sequence_ = 0;
};

}  // namespace kestrel::mavlink
