// MAVLink 2 signing (signing.hpp): the signature against one computed independently, what a
// receiver accepts and refuses (tampering, another key, replays, stale new streams, unsigned
// frames by mode), the sender's timestamps, and key files.
#include <gmock/gmock.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <kestrel/error.hpp>

#include "kestrel/mavlink/frame_parser.hpp"
#include "kestrel/mavlink/messages.hpp"
#include "kestrel/mavlink/signing.hpp"

using namespace kestrel::mavlink;
using Bytes = std::vector<std::uint8_t>;

namespace {

SigningKey counting_key() {
  SigningKey key{};
  for (std::size_t i = 0; i < key.size(); ++i) key[i] = static_cast<std::uint8_t>(i);
  return key;
}

Heartbeat px4_heartbeat() {
  Heartbeat hb;
  hb.type = mav::type_quadrotor;
  hb.autopilot = mav::autopilot_px4;
  hb.base_mode = 129;
  hb.custom_mode = 393216;
  hb.system_status = mav::state_active;
  return hb;
}

Frame parse_one(const Bytes& bytes) {
  FrameParser parser;
  auto frames = parser.feed(bytes);
  EXPECT_EQ(frames.size(), 1u);
  return frames.empty() ? Frame{} : frames.front();
}

// A clock the test moves by hand.
struct ManualClock {
  SigningTimestamp now = 100'000'000;
  Signing::Clock clock() {
    return [this] { return now; };
  }
};

std::filesystem::path temp_file(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("kestrel_signing_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto path = dir / name;
  std::filesystem::remove(path);
  return path;
}

void write_file(const std::filesystem::path& path, const std::string& contents, mode_t mode) {
  std::ofstream(path, std::ios::binary) << contents;
  ::chmod(path.c_str(), mode);
}

}  // namespace

TEST(MavlinkSigning, TheSignatureIsTheFirst48BitsOfSha256OverKeyAndFrame) {
  // Computed with Python's hashlib and a CRC-16/MCRF4XX of its own, from the MAVLink guide's
  // formula: sha256(key + header + payload + crc + link id + timestamp)[:6].
  const Heartbeat hb = px4_heartbeat();
  Bytes frame = encode_v2(Heartbeat::definition(), &hb, {1, 1}, 7, incompat_signed);
  append_signature(frame, counting_key(), 3, 0x123456789A);
  EXPECT_EQ(to_hex(frame), "fd09010007010100000000000600020c81040376db039a78563412001fbd8940f41b");
  const Frame f = parse_one(frame);
  EXPECT_TRUE(f.is_signed());
  EXPECT_EQ(f.link_id(), 3);
  EXPECT_EQ(f.signature_timestamp(), 0x123456789Au);
  EXPECT_TRUE(signature_matches(f, counting_key()));
  SigningKey other = counting_key();
  other[31] ^= 1;
  EXPECT_FALSE(signature_matches(f, other));
}

TEST(MavlinkSigning, AReceiverAcceptsFreshFramesOfItsKeyAndRefusesTheRest) {
  ManualClock clock;
  Signing autopilot(SigningMode::require, counting_key(), 0, clock.clock());
  Signing companion(SigningMode::require, counting_key(), 0, clock.clock());
  const Heartbeat hb = px4_heartbeat();
  const Bytes first = autopilot.encode(Heartbeat::definition(), &hb, {1, 1}, 0);
  const Bytes second = autopilot.encode(Heartbeat::definition(), &hb, {1, 1}, 1);
  EXPECT_EQ(companion.check(parse_one(first)), SignatureCheck::good);
  EXPECT_EQ(companion.check(parse_one(first)), SignatureCheck::replayed) << "the same frame again";
  EXPECT_EQ(companion.check(parse_one(second)), SignatureCheck::good);
  EXPECT_EQ(companion.check(parse_one(first)), SignatureCheck::replayed) << "an older frame of the stream";

  // A byte of the payload changed, the checksum made good again: only the signature catches it.
  Bytes tampered = autopilot.encode(Heartbeat::definition(), &hb, {1, 1}, 2);
  tampered[header_v2] ^= 0x01;
  const std::size_t crc_at = header_v2 + tampered[1];
  const std::uint16_t crc =
      frame_checksum(std::span(tampered).subspan(1, header_v2 - 1 + tampered[1]), Heartbeat::definition().crc_extra());
  tampered[crc_at] = static_cast<std::uint8_t>(crc & 0xFF);
  tampered[crc_at + 1] = static_cast<std::uint8_t>(crc >> 8);
  EXPECT_EQ(companion.check(parse_one(tampered)), SignatureCheck::bad_signature);

  SigningKey other_key = counting_key();
  other_key[0] = 0xAA;
  Signing impostor(SigningMode::require, other_key, 0, clock.clock());
  EXPECT_EQ(companion.check(parse_one(impostor.encode(Heartbeat::definition(), &hb, {1, 1}, 3))),
            SignatureCheck::bad_signature);
  EXPECT_EQ(companion.check(parse_one(encode_v2(Heartbeat::definition(), &hb, {1, 1}, 4))),
            SignatureCheck::unsigned_frame);
}

TEST(MavlinkSigning, StreamsAreKeptApartBySystemComponentAndLink) {
  ManualClock clock;
  Signing receiver(SigningMode::require, counting_key(), 0, clock.clock());
  const Heartbeat hb = px4_heartbeat();
  const auto frame_at = [&](Sender from, std::uint8_t link, SigningTimestamp t) {
    Bytes b = encode_v2(Heartbeat::definition(), &hb, from, 0, incompat_signed);
    append_signature(b, counting_key(), link, t);
    return parse_one(b);
  };
  EXPECT_EQ(receiver.check(frame_at({1, 1}, 0, clock.now)), SignatureCheck::good);
  // Each of these starts a stream of its own, so the same timestamp is fresh for it.
  EXPECT_EQ(receiver.check(frame_at({1, 1}, 1, clock.now)), SignatureCheck::good);
  EXPECT_EQ(receiver.check(frame_at({1, 2}, 0, clock.now)), SignatureCheck::good);
  EXPECT_EQ(receiver.check(frame_at({2, 1}, 0, clock.now)), SignatureCheck::good);
  EXPECT_EQ(receiver.check(frame_at({1, 1}, 0, clock.now)), SignatureCheck::replayed);
  // A new stream may start up to a minute behind the receiver's clock, not more.
  EXPECT_EQ(receiver.check(frame_at({3, 1}, 0, clock.now - new_stream_tolerance)), SignatureCheck::good);
  EXPECT_EQ(receiver.check(frame_at({4, 1}, 0, clock.now - new_stream_tolerance - 1)), SignatureCheck::replayed);
}

TEST(MavlinkSigning, OwnTimestampsRiseEveryFrameAndPassTheNewestAccepted) {
  ManualClock clock;
  Signing end(SigningMode::sign, counting_key(), 5, clock.clock());
  const Heartbeat hb = px4_heartbeat();
  const auto stamp_of_next = [&] {
    return parse_one(end.encode(Heartbeat::definition(), &hb, {1, 1}, 0)).signature_timestamp();
  };
  EXPECT_EQ(stamp_of_next(), clock.now);
  EXPECT_EQ(stamp_of_next(), clock.now + 1) << "a clock that has not moved: one more than the last";
  clock.now -= 500;  // a clock stepped back never makes a timestamp repeat
  EXPECT_EQ(stamp_of_next(), clock.now + 502);
  // A peer whose clock runs ahead: after accepting its frame, ours are newer than it.
  Bytes ahead = encode_v2(Heartbeat::definition(), &hb, {9, 1}, 0, incompat_signed);
  append_signature(ahead, counting_key(), 0, clock.now + 1'000'000);
  ASSERT_EQ(end.check(parse_one(ahead)), SignatureCheck::good);
  EXPECT_EQ(stamp_of_next(), clock.now + 1'000'001);
  EXPECT_EQ(parse_one(end.encode(Heartbeat::definition(), &hb, {1, 1}, 0)).link_id(), 5);
}

TEST(MavlinkSigning, SignAcceptsUnsignedFramesRequireDropsThemAndEveryVerdictIsCounted) {
  ManualClock clock;
  Signing sign(SigningMode::sign, counting_key(), 0, clock.clock());
  Signing require(SigningMode::require, counting_key(), 0, clock.clock());
  Signing sender(SigningMode::sign, counting_key(), 0, clock.clock());
  const Heartbeat hb = px4_heartbeat();
  const Frame plain = parse_one(encode_v2(Heartbeat::definition(), &hb, {1, 1}, 0));
  const Frame good = parse_one(sender.encode(Heartbeat::definition(), &hb, {1, 1}, 0));
  EXPECT_TRUE(sign.admit(plain));
  EXPECT_FALSE(require.admit(plain));
  EXPECT_TRUE(sign.admit(good));
  EXPECT_TRUE(require.admit(good));
  EXPECT_FALSE(sign.admit(good)) << "a replay is refused in either mode";
  EXPECT_FALSE(require.admit(good));
  const SigningCounts c = require.counts();
  EXPECT_EQ(c.unsigned_frames, 1u);
  EXPECT_EQ(c.signed_frames, 1u);
  EXPECT_EQ(c.replayed, 1u);
  EXPECT_EQ(c.bad_signature, 0u);
  EXPECT_THROW(Signing(SigningMode::off, counting_key(), 0), kestrel::Error);
}

TEST(MavlinkSigningKey, ReadsHexOrRawBytesReadableByItsOwnerOnly) {
  const auto hex = temp_file("hex.key");
  write_file(hex, "  " + to_hex(counting_key()) + "\n", 0600);
  EXPECT_EQ(load_signing_key(hex), counting_key());
  const auto raw = temp_file("raw.key");
  const SigningKey k = counting_key();
  write_file(raw, std::string(k.begin(), k.end()), 0400);
  EXPECT_EQ(load_signing_key(raw), counting_key());

  const auto open = temp_file("open.key");
  write_file(open, to_hex(counting_key()), 0644);
  EXPECT_THAT([&] { load_signing_key(open); }, ::testing::ThrowsMessage<kestrel::Error>(::testing::AllOf(
                                                   ::testing::HasSubstr(open.string()), ::testing::HasSubstr("0644"),
                                                   ::testing::HasSubstr("chmod 600"))));
  const auto short_key = temp_file("short.key");
  write_file(short_key, "abcd\n", 0600);
  EXPECT_THAT([&] { load_signing_key(short_key); },
              ::testing::ThrowsMessage<kestrel::Error>(::testing::HasSubstr("32 bytes or 64 hexadecimal")));
  const auto not_hex = temp_file("nothex.key");
  write_file(not_hex, std::string(63, 'a') + "g", 0600);
  EXPECT_THAT([&] { load_signing_key(not_hex); },
              ::testing::ThrowsMessage<kestrel::Error>(::testing::HasSubstr("character 64")));
  EXPECT_THAT([&] { load_signing_key(temp_file("missing.key")); },
              ::testing::ThrowsMessage<kestrel::Error>(::testing::HasSubstr("keygen")));
  EXPECT_THROW(load_signing_key(""), kestrel::Error);
}

TEST(MavlinkSigningKey, ANewKeyIsRandomOwnerOnlyAndNeverOverwritten) {
  const auto path = temp_file("new.key");
  const SigningKey key = random_signing_key();
  EXPECT_NE(key, random_signing_key());
  write_signing_key(path, key);
  struct stat st {};
  ASSERT_EQ(::stat(path.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0600u);
  EXPECT_EQ(load_signing_key(path), key);
  EXPECT_THAT([&] { write_signing_key(path, random_signing_key()); },
              ::testing::ThrowsMessage<kestrel::Error>(::testing::HasSubstr("never overwritten")));
  EXPECT_EQ(load_signing_key(path), key);
}
