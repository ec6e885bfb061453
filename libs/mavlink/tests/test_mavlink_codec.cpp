// The MAVLink codec against what can be checked without it: the published CRC_EXTRA constants and
// lengths of common.xml's messages, the standard check value of CRC-16/MCRF4XX, and frames
// captured from other implementations (a MAVLink 1 heartbeat from a tutorial's packet dump, a
// MAVLink 2 heartbeat from an ArduPilot antenna tracker in another library's test suite).
#include <gmock/gmock.h>

#include <map>
#include <random>
#include <string_view>

#include "kestrel/mavlink/crc16.hpp"
#include "kestrel/mavlink/frame.hpp"
#include "kestrel/mavlink/frame_parser.hpp"
#include "kestrel/mavlink/message_text.hpp"
#include "kestrel/mavlink/messages.hpp"

using namespace kestrel::mavlink;
using Bytes = std::vector<std::uint8_t>;

namespace {

Bytes concat(std::initializer_list<Bytes> parts) {
  Bytes out;
  for (const Bytes& p : parts) out.insert(out.end(), p.begin(), p.end());
  return out;
}

}  // namespace

TEST(MavlinkCrc, TheCheckValueOfCrc16Mcrf4xx) {
  EXPECT_EQ(crc16_accumulate(std::string_view("123456789"), crc16_initial), 0x6F91);
}

TEST(MavlinkMessages, CrcExtraAndLengthsAreThePublishedOnes) {
  // {CRC_EXTRA, MIN_LEN, LEN} of the generated C library (common.h, MAVLINK_MESSAGE_CRCS).
  const std::map<std::uint32_t, std::array<int, 3>> published = {
      {0, {50, 9, 9}},    {1, {124, 31, 43}},  {31, {246, 32, 48}}, {32, {185, 28, 28}},  {76, {152, 33, 33}},
      {77, {143, 3, 10}}, {82, {49, 39, 51}},  {83, {22, 37, 37}},  {84, {143, 53, 53}},  {85, {140, 51, 51}},
      {245, {130, 2, 2}}, {253, {83, 51, 54}}, {256, {71, 42, 42}}, {331, {91, 230, 233}}};
  ASSERT_EQ(known_definitions().size(), published.size());
  for (const MessageDefinition* d : known_definitions()) {
    SCOPED_TRACE(std::string(d->name()));
    ASSERT_TRUE(published.contains(d->id()));
    const auto& [crc_extra, min_length, length] = published.at(d->id());
    EXPECT_EQ(d->crc_extra(), crc_extra);
    EXPECT_EQ(d->min_length(), static_cast<std::size_t>(min_length));
    EXPECT_EQ(d->length(), static_cast<std::size_t>(length));
    EXPECT_EQ(find_definition(d->id()), d);
  }
  EXPECT_EQ(find_definition(9999), nullptr);
}

TEST(MavlinkMessages, WireOrderSortsBaseFieldsByElementSizeAndPutsExtensionsLast) {
  const auto offsets = [](const MessageDefinition& d) {
    std::map<std::string, std::size_t> m;
    for (const WireField& w : d.wire()) m[std::string(w.field->name)] = w.offset;
    return m;
  };
  // The offsets of the generated C headers.
  const auto sat = offsets(SetAttitudeTarget::definition());
  EXPECT_EQ(sat.at("time_boot_ms"), 0u);
  EXPECT_EQ(sat.at("q"), 4u);
  EXPECT_EQ(sat.at("thrust"), 32u);
  EXPECT_EQ(sat.at("target_system"), 36u);
  EXPECT_EQ(sat.at("type_mask"), 38u);
  EXPECT_EQ(sat.at("thrust_body"), 39u);
  const auto odometry = offsets(Odometry::definition());
  EXPECT_EQ(odometry.at("x"), 8u);
  EXPECT_EQ(odometry.at("pose_covariance"), 60u);
  EXPECT_EQ(odometry.at("velocity_covariance"), 144u);
  EXPECT_EQ(odometry.at("frame_id"), 228u);
  EXPECT_EQ(odometry.at("quality"), 232u);
  const auto command = offsets(CommandLong::definition());
  EXPECT_EQ(command.at("param1"), 0u);
  EXPECT_EQ(command.at("command"), 28u);
  EXPECT_EQ(command.at("confirmation"), 32u);
}

TEST(MavlinkFrames, ADocumentedMavlink1HeartbeatDecodesAndEncodesByteForByte) {
  // seq 0x4E, system 1, component 1: a quadrotor (2) on ArduPilot (3), base_mode 0x51, active (4).
  const Bytes captured = {0xFE, 0x09, 0x4E, 0x01, 0x01, 0x00, 0x00, 0x00, 0x00,
                          0x00, 0x02, 0x03, 0x51, 0x04, 0x03, 0x1C, 0x7F};
  FrameParser parser;
  const auto frames = parser.feed(captured);
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].version, 1);
  EXPECT_EQ(frames[0].sequence, 0x4E);
  const auto hb = frames[0].as<Heartbeat>();
  EXPECT_EQ(hb.type, 2);
  EXPECT_EQ(hb.autopilot, 3);
  EXPECT_EQ(hb.base_mode, 0x51);
  EXPECT_EQ(hb.custom_mode, 0u);
  EXPECT_EQ(hb.system_status, 4);
  EXPECT_EQ(hb.mavlink_version, 3);
  EXPECT_EQ(encode_v1(Heartbeat::definition(), &hb, {1, 1}, 0x4E), captured);
  EXPECT_EQ(parser.counts().v1_frames, 1u);
}

TEST(MavlinkFrames, ADocumentedMavlink2HeartbeatDecodesAndEncodesByteForByte) {
  // seq 7, system 42, component 150: an antenna tracker (5) on ArduPilot (3), custom_mode 68.
  const Bytes captured = {0xFD, 0x09, 0x00, 0x00, 0x07, 0x2A, 0x96, 0x00, 0x00, 0x00, 0x44,
                          0x00, 0x00, 0x00, 0x05, 0x03, 0x2D, 0x0D, 0x02, 0x7E, 0xFD};
  FrameParser parser;
  const auto frames = parser.feed(captured);
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].system_id, 42);
  EXPECT_EQ(frames[0].component_id, 150);
  const auto hb = frames[0].as<Heartbeat>();
  EXPECT_EQ(hb.custom_mode, 68u);
  EXPECT_EQ(hb.type, 5);
  EXPECT_EQ(hb.autopilot, 3);
  EXPECT_EQ(hb.base_mode, 0x2D);
  EXPECT_EQ(hb.system_status, 0x0D);
  EXPECT_EQ(hb.mavlink_version, 2);
  EXPECT_EQ(encode_v2(Heartbeat::definition(), &hb, {42, 150}, 7), captured);
  EXPECT_EQ(message_text(Heartbeat::definition(), frames[0].payload),
            "HEARTBEAT type=5 autopilot=3 base_mode=45 custom_mode=68 system_status=13 mavlink_version=2");
}

TEST(MavlinkFrames, TrailingZerosAreCutAndReadBackAsZero) {
  CommandAck ack;
  ack.command = 400;  // 0x0190: payload 90 01 00 | 00 00 00 00 00 00 00
  ack.result = 0;
  const Bytes frame = encode_v2(CommandAck::definition(), &ack, {1, 1}, 0);
  ASSERT_EQ(frame[1], 2);  // only "90 01" is left
  EXPECT_EQ(frame.size(), header_v2 + 2 + checksum_size);
  FrameParser parser;
  const auto frames = parser.feed(frame);
  ASSERT_EQ(frames.size(), 1u);
  const auto back = frames[0].as<CommandAck>();
  EXPECT_EQ(back.command, 400);
  EXPECT_EQ(back.result, 0);
  EXPECT_EQ(back.result_param2, 0);

  // An all-zero payload keeps one byte.
  const ExtendedSysState zero;
  EXPECT_EQ(encode_v2(ExtendedSysState::definition(), &zero, {1, 1}, 0)[1], 1);
}

TEST(MavlinkFrames, EveryFieldOfALargeMessageRoundTrips) {
  Odometry o;
  o.time_usec = 0x0102030405060708ull;
  o.frame_id = 1;
  o.child_frame_id = 12;
  o.x = 1.5f;
  o.y = -2.25f;
  o.z = -3.0f;
  o.q = {0.5f, 0.5f, -0.5f, 0.5f};
  o.vx = 0.1f;
  o.yawspeed = -0.7f;
  for (std::size_t i = 0; i < o.pose_covariance.size(); ++i) o.pose_covariance[i] = static_cast<float>(i);
  o.velocity_covariance[20] = 9.0f;
  o.reset_counter = 3;
  o.estimator_type = 8;
  o.quality = -1;
  FrameWriter writer({1, 1});
  FrameParser parser;
  const auto frames = parser.feed(writer.encode(o));
  ASSERT_EQ(frames.size(), 1u);
  const auto back = frames[0].as<Odometry>();
  EXPECT_EQ(back.time_usec, o.time_usec);
  EXPECT_EQ(back.q, o.q);
  EXPECT_EQ(back.y, o.y);
  EXPECT_EQ(back.yawspeed, o.yawspeed);
  EXPECT_EQ(back.pose_covariance, o.pose_covariance);
  EXPECT_EQ(back.velocity_covariance, o.velocity_covariance);
  EXPECT_EQ(back.child_frame_id, 12);
  EXPECT_EQ(back.quality, -1);
  EXPECT_EQ(back.estimator_type, 8);

  StatusText text;
  text.severity = mav::severity_warning;
  text.set_text("Preflight Fail: \"geofence\"");
  const auto t = parser.feed(writer.encode(text));
  ASSERT_EQ(t.size(), 1u);
  EXPECT_EQ(t[0].as<StatusText>().text_string(), "Preflight Fail: \"geofence\"");
  EXPECT_EQ(t[0].sequence, 1);
  EXPECT_THAT(message_text(StatusText::definition(), t[0].payload),
              ::testing::StartsWith("STATUSTEXT severity=4 text=\"Preflight Fail: \\\"geofence\\\"\" id=0"));
}

TEST(MavlinkParser, FindsTheFramesAmongGarbageAndCountsWhatItRefused) {
  FrameWriter writer({1, 1});
  LocalPositionNed p;
  p.x = 1;
  const Bytes a = writer.encode(p);
  const Bytes b = writer.encode(Heartbeat{});
  Bytes corrupt = writer.encode(p);
  corrupt[12] ^= 0x40;  // a payload bit flipped
  const Bytes c = writer.encode(ExtendedSysState{});
  // 0xFE 0xFD poses as a MAVLink 1 header of 253 bytes: the frames after it are decided once that
  // many bytes have come (the zeros stand for the link's further traffic).
  const Bytes stream = concat({{0x00, 0x13, 0xFD, 0x02}, a, {0xFE, 0xFD}, b, corrupt, {0x55}, c, Bytes(300, 0)});

  FrameParser whole;
  const auto frames = whole.feed(stream);
  ASSERT_EQ(frames.size(), 3u);
  EXPECT_TRUE(frames[0].is<LocalPositionNed>());
  EXPECT_TRUE(frames[1].is<Heartbeat>());
  EXPECT_TRUE(frames[2].is<ExtendedSysState>());
  EXPECT_GE(whole.counts().bad_checksum, 1u);
  EXPECT_EQ(whole.pending(), 0u);

  // Byte by byte: the same frames.
  FrameParser trickle;
  std::vector<Frame> one_by_one;
  for (const std::uint8_t byte : stream)
    for (Frame& f : trickle.feed(std::span(&byte, 1))) one_by_one.push_back(std::move(f));
  ASSERT_EQ(one_by_one.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(one_by_one[i].message_id, frames[i].message_id);
    EXPECT_EQ(one_by_one[i].payload, frames[i].payload);
  }
  EXPECT_EQ(trickle.counts().frames, whole.counts().frames);
}

TEST(MavlinkParser, AnUnknownIdIsCountedAndSteppedOverByItsLength) {
  // A well-formed frame of id 147 (BATTERY_STATUS), unknown here; its payload holds a magic byte.
  Bytes unknown = {0xFD, 4, 0, 0, 9, 1, 1, 147, 0, 0, 0xFD, 0xFD, 0xFD, 0xFD, 0x12, 0x34};
  FrameWriter writer({1, 1});
  const Bytes stream = concat({unknown, writer.encode(Heartbeat{})});
  FrameParser parser;
  const auto frames = parser.feed(stream);
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_TRUE(frames[0].is<Heartbeat>());
  EXPECT_EQ(parser.counts().unknown_id, 1u);
  EXPECT_EQ(parser.counts().bytes_skipped, 0u);
}

TEST(MavlinkParser, ASignedFrameIsReadAndItsSignatureSteppedOver) {
  FrameWriter writer({1, 1});
  Bytes signed_frame = writer.encode(Heartbeat{});
  signed_frame[2] = incompat_signed;  // the flags are covered by the checksum: compute it again
  signed_frame.resize(signed_frame.size() - 2);
  const std::uint16_t crc = frame_checksum(std::span(signed_frame).subspan(1), Heartbeat::definition().crc_extra());
  signed_frame.push_back(crc & 0xFF);
  signed_frame.push_back(crc >> 8);
  for (int i = 0; i < 13; ++i) signed_frame.push_back(static_cast<std::uint8_t>(0xFD));  // link id, stamp, signature
  FrameParser parser;
  const auto frames = parser.feed(concat({signed_frame, writer.encode(ExtendedSysState{})}));
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_TRUE(frames[0].is_signed());
  EXPECT_TRUE(frames[1].is<ExtendedSysState>());
  EXPECT_EQ(parser.counts().signed_frames, 1u);
  EXPECT_EQ(parser.counts().bytes_skipped, 0u);
}

TEST(MavlinkParser, UnknownIncompatibilityFlagsAreRefused) {
  FrameWriter writer({1, 1});
  Bytes frame = writer.encode(Heartbeat{});
  frame[2] = 0x02;
  FrameParser parser;
  EXPECT_TRUE(parser.feed(frame).empty());
  EXPECT_EQ(parser.counts().bad_flags, 1u);
}

TEST(MavlinkParser, APayloadLongerThanOursIsANewerDefinitionAndIsRead) {
  // A sender with one more extension field than we know: its bytes are ignored, not refused.
  LocalPositionNed p;
  p.vz = -4.0f;
  Bytes payload = LocalPositionNed::definition().write(&p);
  payload.push_back(0x77);
  Bytes frame = {0xFD, static_cast<std::uint8_t>(payload.size()), 0, 0, 0, 1, 1, 32, 0, 0};
  frame.insert(frame.end(), payload.begin(), payload.end());
  const std::uint16_t crc = frame_checksum(std::span(frame).subspan(1), LocalPositionNed::definition().crc_extra());
  frame.push_back(crc & 0xFF);
  frame.push_back(crc >> 8);
  FrameParser parser;
  const auto frames = parser.feed(frame);
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].as<LocalPositionNed>().vz, -4.0f);
}

TEST(MavlinkParser, NoisePosingAsAHeaderOfAnUnknownIdSwallowsNoRealFrame) {
  // 0xFD, length 40, id 0x7F7F7F: a "frame" that would cover the heartbeat after it.
  FrameWriter writer({1, 1});
  const Bytes stream =
      concat({{0xFD, 40, 0, 0, 0, 1, 1, 0x7F, 0x7F, 0x7F}, writer.encode(Heartbeat{}), Bytes(40, 0x11)});
  FrameParser parser;
  const auto frames = parser.feed(stream);
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_TRUE(frames[0].is<Heartbeat>());
  EXPECT_EQ(parser.counts().unknown_id, 0u);
}

TEST(MavlinkParser, RandomNoiseBetweenFramesLosesNoFrame) {
  std::mt19937 rng(7);
  FrameWriter writer({1, 1});
  FrameParser parser;
  std::size_t sent = 0, received = 0;
  const auto count = [&](const std::vector<Frame>& frames) {
    for (const Frame& f : frames) received += f.is<AttitudeQuaternion>() ? 1 : 0;
  };
  for (int round = 0; round < 500; ++round) {
    Bytes noise(rng() % 40);
    for (auto& b : noise) b = static_cast<std::uint8_t>(rng() % 8 == 0 ? 0xFD : rng());
    count(parser.feed(noise));
    AttitudeQuaternion q;
    q.time_boot_ms = static_cast<std::uint32_t>(round);
    ++sent;
    count(parser.feed(writer.encode(q)));
  }
  count(parser.feed(Bytes(300, 0)));
  EXPECT_EQ(received, sent);
  EXPECT_EQ(parser.counts().frames, sent);
}
