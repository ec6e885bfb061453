#pragma once
// MAVLink 2 message signing (the "Message Signing" chapter of the MAVLink guide). A signed frame
// sets incompatibility flag 0x01 and carries 13 more bytes: the sender's link id, a 48-bit
// timestamp (10 us units since 2015-01-01 UTC) and the first 48 bits of
//   SHA-256(secret key + header + payload + checksum + link id + timestamp),
// the header starting at the magic byte. A receiver keeps the last timestamp of each stream
// (system id, component id, link id) and refuses one not newer (a replay), and a new stream more
// than a minute behind its own clock. Its own timestamps follow its clock, rise by at least one a
// frame, and never fall behind the newest it has accepted, as the specification asks.
#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <span>
#include <string>
#include <tuple>
#include <vector>

#include "kestrel/mavlink/frame.hpp"

namespace kestrel::mavlink {

inline constexpr std::size_t signing_key_size = 32;
using SigningKey = std::array<std::uint8_t, signing_key_size>;

/// The timestamp a signature carries: 10 us units since 2015-01-01 00:00 UTC.
using SigningTimestamp = std::uint64_t;
inline constexpr SigningTimestamp max_signing_timestamp = (SigningTimestamp{1} << 48) - 1;
/// How far behind the receiver's clock a new stream may start (one minute).
inline constexpr SigningTimestamp new_stream_tolerance = 6'000'000;
/// Now, from the system clock.
SigningTimestamp signing_timestamp_now();

/// Appends link id, timestamp and signature to a version 2 frame whose flags say it is signed
/// (encode_v2(..., incompat_signed)).
void append_signature(std::vector<std::uint8_t>& frame, const SigningKey& key, std::uint8_t link_id,
                      SigningTimestamp timestamp);
/// The 6 bytes a frame's signature must hold: `signed_part` runs from the magic byte to the end
/// of the timestamp.
std::array<std::uint8_t, 6> compute_signature(const SigningKey& key, std::span<const std::uint8_t> signed_part);
/// Whether a received frame's signature is the one `key` gives (timestamps not judged).
bool signature_matches(const Frame& frame, const SigningKey& key);

enum class SigningMode {
  off,      ///< frames go out unsigned; received signatures are not checked
  sign,     ///< frames go out signed; signed frames are checked, unsigned ones still accepted
  require,  ///< frames go out signed; only correctly signed, fresh frames are accepted
};

enum class SignatureCheck { good, unsigned_frame, bad_signature, replayed };

struct SigningCounts {
  std::uint64_t signed_frames = 0;    ///< accepted: signature right, timestamp fresh
  std::uint64_t unsigned_frames = 0;  ///< received unsigned (dropped under `require`)
  std::uint64_t bad_signature = 0;    ///< dropped: the signature is not the key's
  std::uint64_t replayed = 0;         ///< dropped: not newer than its stream's last, or a stale new stream
};

/// One end's signing: its key and link id, its own timestamp, and the last timestamp of every
/// stream it has accepted. Safe to share between a sending and a receiving thread.
class Signing {
 public:
  using Clock = std::function<SigningTimestamp()>;
  /// `mode` is sign or require (`off` is no Signing at all).
  Signing(SigningMode mode, const SigningKey& key, std::uint8_t link_id, Clock clock = signing_timestamp_now);

  SigningMode mode() const { return mode_; }
  std::uint8_t link_id() const { return link_id_; }
  const SigningKey& key() const { return key_; }

  /// A signed version 2 frame, with the next timestamp.
  std::vector<std::uint8_t> encode(const MessageDefinition& definition, const void* message, Sender from,
                                   std::uint8_t sequence);
  /// Judges a received frame, remembering its timestamp when it is good.
  SignatureCheck check(const Frame& frame);
  /// Whether a received frame may be used under this mode; counts it either way.
  bool admit(const Frame& frame);
  SigningCounts counts() const;

 private:
  SigningTimestamp next_timestamp();

  SigningMode mode_;
  SigningKey key_;
  std::uint8_t link_id_;
  Clock clock_;
  mutable std::mutex mutex_;
  SigningTimestamp last_sent_ = 0;
  std::map<std::tuple<std::uint8_t, std::uint8_t, std::uint8_t>, SigningTimestamp> streams_;
  SigningCounts counts_;
};

/// A key from a file: 32 bytes, or 64 hexadecimal characters (surrounding white space ignored).
/// Throws kestrel::Error, naming the file: missing, unreadable, readable by group or others
/// (a secret must be the owner's alone), or neither form.
SigningKey load_signing_key(const std::string& path);
/// The key in `contents` (either form). Throws kestrel::Error beginning with `what`.
SigningKey parse_signing_key(std::span<const std::uint8_t> contents, const std::string& what);
/// 32 bytes from the operating system's random source (OpenSSL's RAND_bytes).
SigningKey random_signing_key();
/// Writes a key as 64 hexadecimal characters and a newline, readable by its owner only; refuses
/// to replace an existing file. Throws kestrel::Error.
void write_signing_key(const std::string& path, const SigningKey& key);
std::string to_hex(std::span<const std::uint8_t> bytes);

}  // namespace kestrel::mavlink
