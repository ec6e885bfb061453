#include "kestrel/mavlink/signing.hpp"

#include <fcntl.h>
#include <openssl/evp.h>
#include <openssl/rand.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <fstream>
#include <iterator>
#include <kestrel/error.hpp>

namespace kestrel::mavlink {

namespace {

// 2015-01-01 00:00 UTC in Unix seconds: the signing epoch.
constexpr std::int64_t kSigningEpochUnixS = 1420070400;

// The bytes a signature covers, rebuilt from a parsed frame: header from the magic byte, payload
// as received, checksum, link id and timestamp.
std::vector<std::uint8_t> signed_part_of(const Frame& f) {
  std::vector<std::uint8_t> out;
  out.reserve(header_v2 + f.payload.size() + checksum_size + 7);
  out.insert(out.end(), {magic_v2, static_cast<std::uint8_t>(f.payload.size()), f.incompat_flags, f.compat_flags,
                         f.sequence, f.system_id, f.component_id, static_cast<std::uint8_t>(f.message_id & 0xFF),
                         static_cast<std::uint8_t>((f.message_id >> 8) & 0xFF),
                         static_cast<std::uint8_t>((f.message_id >> 16) & 0xFF)});
  out.insert(out.end(), f.payload.begin(), f.payload.end());
  out.push_back(static_cast<std::uint8_t>(f.checksum & 0xFF));
  out.push_back(static_cast<std::uint8_t>(f.checksum >> 8));
  out.insert(out.end(), f.signature.begin(), f.signature.begin() + 7);
  return out;
}

int hex_digit(std::uint8_t c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

bool is_space(std::uint8_t c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; }

}  // namespace

SigningTimestamp signing_timestamp_now() {
  const auto us =
      std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch())
          .count();
  const std::int64_t units = us / 10 - kSigningEpochUnixS * 100'000;
  return units > 0 ? static_cast<SigningTimestamp>(units) : 0;
}

std::array<std::uint8_t, 6> compute_signature(const SigningKey& key, std::span<const std::uint8_t> signed_part) {
  std::array<std::uint8_t, signing_key_size + max_frame_size> input{};
  if (signed_part.size() > max_frame_size) throw Error("MAVLink signature: frame too long");
  std::copy(key.begin(), key.end(), input.begin());
  std::copy(signed_part.begin(), signed_part.end(), input.begin() + signing_key_size);
  std::array<std::uint8_t, EVP_MAX_MD_SIZE> digest{};
  unsigned int digest_size = 0;
  if (EVP_Digest(input.data(), signing_key_size + signed_part.size(), digest.data(), &digest_size, EVP_sha256(),
                 nullptr) != 1)
    throw Error("MAVLink signature: SHA-256 failed");
  std::array<std::uint8_t, 6> out{};
  std::copy(digest.begin(), digest.begin() + 6, out.begin());
  return out;
}

void append_signature(std::vector<std::uint8_t>& frame, const SigningKey& key, std::uint8_t link_id,
                      SigningTimestamp timestamp) {
  frame.push_back(link_id);
  for (int i = 0; i < 6; ++i) frame.push_back(static_cast<std::uint8_t>(timestamp >> (8 * i)));
  const auto signature = compute_signature(key, frame);
  frame.insert(frame.end(), signature.begin(), signature.end());
}

bool signature_matches(const Frame& frame, const SigningKey& key) {
  if (frame.version != 2 || !frame.is_signed()) return false;
  const auto expected = compute_signature(key, signed_part_of(frame));
  return std::equal(expected.begin(), expected.end(), frame.signature.begin() + 7);
}

Signing::Signing(SigningMode mode, const SigningKey& key, std::uint8_t link_id, Clock clock)
    : mode_(mode), key_(key), link_id_(link_id), clock_(std::move(clock)) {
  if (mode_ == SigningMode::off) throw Error("MAVLink signing: mode off has no signing state");
}

SigningTimestamp Signing::next_timestamp() {
  last_sent_ = std::min(std::max(clock_(), last_sent_ + 1), max_signing_timestamp);
  return last_sent_;
}

std::vector<std::uint8_t> Signing::encode(const MessageDefinition& definition, const void* message, Sender from,
                                          std::uint8_t sequence) {
  std::vector<std::uint8_t> frame = encode_v2(definition, message, from, sequence, incompat_signed);
  std::lock_guard lock(mutex_);
  append_signature(frame, key_, link_id_, next_timestamp());
  return frame;
}

SignatureCheck Signing::check(const Frame& frame) {
  if (!frame.is_signed()) return SignatureCheck::unsigned_frame;
  if (!signature_matches(frame, key_)) return SignatureCheck::bad_signature;
  const SigningTimestamp stamp = frame.signature_timestamp();
  std::lock_guard lock(mutex_);
  const auto stream = std::make_tuple(frame.system_id, frame.component_id, frame.link_id());
  const auto it = streams_.find(stream);
  if (it == streams_.end()) {
    // A new stream must not be older than a minute behind us: an old capture replayed to a
    // receiver that never heard its stream.
    const SigningTimestamp ours = std::max(clock_(), last_sent_);
    if (stamp + new_stream_tolerance < ours) return SignatureCheck::replayed;
    streams_.emplace(stream, stamp);
  } else {
    if (stamp <= it->second) return SignatureCheck::replayed;
    it->second = stamp;
  }
  last_sent_ = std::max(last_sent_, stamp);  // our next timestamp is newer than any we accepted
  return SignatureCheck::good;
}

bool Signing::admit(const Frame& frame) {
  const SignatureCheck verdict = check(frame);
  std::lock_guard lock(mutex_);
  switch (verdict) {
    case SignatureCheck::good:
      ++counts_.signed_frames;
      return true;
    case SignatureCheck::unsigned_frame:
      ++counts_.unsigned_frames;
      return mode_ != SigningMode::require;
    case SignatureCheck::bad_signature:
      ++counts_.bad_signature;
      return false;
    case SignatureCheck::replayed:
      ++counts_.replayed;
      return false;
  }
  return false;
}

SigningCounts Signing::counts() const {
  std::lock_guard lock(mutex_);
  return counts_;
}

SigningKey parse_signing_key(std::span<const std::uint8_t> contents, const std::string& what) {
  SigningKey key{};
  if (contents.size() == signing_key_size) {
    std::copy(contents.begin(), contents.end(), key.begin());
    return key;
  }
  auto begin = contents.begin(), end = contents.end();
  while (begin != end && is_space(*begin)) ++begin;
  while (end != begin && is_space(*(end - 1))) --end;
  if (std::distance(begin, end) != static_cast<std::ptrdiff_t>(2 * signing_key_size))
    throw Error(what + ": a signing key is 32 bytes or 64 hexadecimal characters, not " +
                std::to_string(contents.size()) + " bytes");
  for (std::size_t c = 0; c < 2 * signing_key_size; ++c) {
    const int digit = hex_digit(begin[static_cast<std::ptrdiff_t>(c)]);
    if (digit < 0)
      throw Error(what + ": a signing key of 64 characters must be hexadecimal (character " + std::to_string(c + 1) +
                  ")");
    key[c / 2] = static_cast<std::uint8_t>(key[c / 2] * 16 + digit);
  }
  return key;
}

SigningKey load_signing_key(const std::string& path) {
  if (path.empty()) throw Error("signing_key_file is empty: signing needs a key (kestrel mavlink keygen FILE)");
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0)
    throw Error("signing key file " + path + ": " + std::strerror(errno) + " (kestrel mavlink keygen FILE writes one)");
  if (!S_ISREG(st.st_mode)) throw Error("signing key file " + path + ": not a regular file");
  if ((st.st_mode & (S_IRWXG | S_IRWXO)) != 0) {
    char mode[8];
    std::snprintf(mode, sizeof mode, "%04o", static_cast<unsigned>(st.st_mode & 07777));
    throw Error("signing key file " + path + " is open to group or others (mode " + mode +
                "): a secret must be its owner's alone; chmod 600 " + path);
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("signing key file " + path + ": cannot be read");
  std::vector<std::uint8_t> contents;
  char c;
  while (contents.size() <= 4 * signing_key_size && in.get(c)) contents.push_back(static_cast<std::uint8_t>(c));
  return parse_signing_key(contents, "signing key file " + path);
}

SigningKey random_signing_key() {
  SigningKey key{};
  if (RAND_bytes(key.data(), static_cast<int>(key.size())) != 1)
    throw Error("no random bytes for a signing key (OpenSSL RAND_bytes failed)");
  return key;
}

std::string to_hex(std::span<const std::uint8_t> bytes) {
  static constexpr char digits[] = "0123456789abcdef";
  std::string out;
  out.reserve(2 * bytes.size());
  for (std::uint8_t b : bytes) {
    out.push_back(digits[b >> 4]);
    out.push_back(digits[b & 0x0F]);
  }
  return out;
}

void write_signing_key(const std::string& path, const SigningKey& key) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, S_IRUSR | S_IWUSR);
  if (fd < 0) {
    if (errno == EEXIST) throw Error(path + " exists: a key is never overwritten (remove it first)");
    throw Error(path + ": " + std::strerror(errno));
  }
  const std::string text = to_hex(key) + "\n";
  const bool written = ::write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size());
  const bool closed = ::close(fd) == 0;
  if (!written || !closed) {
    ::unlink(path.c_str());
    throw Error(path + ": the key could not be written");
  }
}

}  // namespace kestrel::mavlink
