// The link the nodes share, against a vehicle played by the test over loopback UDP.
#include <gmock/gmock.h>
#include <pty.h>
#include <unistd.h>

#include <array>
#include <kestrel/error.hpp>
#include <thread>

#include "kestrel/mavlink/connection_url.hpp"
#include "kestrel/mavlink/frame_parser.hpp"
#include "kestrel/mavlink/signing.hpp"
#include "kestrel/mavlink/udp_transport.hpp"
#include "kestrel/testing/udp_ports.hpp"
#include "link.hpp"

using namespace kestrel::mavlink;
using namespace std::chrono_literals;

namespace {

template <class Predicate>
bool eventually(Predicate done) {
  for (int i = 0; i < 200; ++i) {
    if (done()) return true;
    std::this_thread::sleep_for(5ms);
  }
  return false;
}

// A link listening on a free loopback port, and that port.
std::pair<std::unique_ptr<Link>, std::uint16_t> listening_link(const LinkOptions& options = {}) {
  auto transport = kestrel::testing::listening_udp();
  const std::uint16_t port = transport->local_port();
  return {std::make_unique<Link>(std::move(transport), options), port};
}

}  // namespace

TEST(MavlinkLink, KeepsTheAutopilotsLatestStateAndSpeaksAsItsCompanion) {
  LinkOptions options;
  options.autopilot_system_id = 7;
  auto [owned, port] = listening_link(options);
  Link& link = *owned;
  UdpTransport vehicle(parse_connection_url("udpout://127.0.0.1:" + std::to_string(port)));
  FrameWriter autopilot({7, mav::comp_autopilot1});
  FrameWriter ground_station({255, 190});

  Heartbeat gcs;
  gcs.autopilot = mav::autopilot_invalid;
  gcs.type = mav::type_gcs;
  vehicle.send(ground_station.encode(gcs));
  Heartbeat hb;
  hb.autopilot = mav::autopilot_px4;
  hb.type = mav::type_quadrotor;
  hb.custom_mode = 6u << 16;
  vehicle.send(autopilot.encode(hb));
  LocalPositionNed p;
  p.x = 3.0f;
  vehicle.send(autopilot.encode(p));
  CommandAck ack;
  ack.command = mav::cmd_component_arm_disarm;
  vehicle.send(autopilot.encode(ack));

  ASSERT_TRUE(eventually([&] { return link.view().position_count == 1 && link.view().heartbeat_count == 1; }));
  const VehicleView view = link.view();
  EXPECT_EQ(view.heartbeat.custom_mode, 6u << 16) << "the ground station's heartbeat is not the autopilot's";
  EXPECT_EQ(view.system_id, 7);
  EXPECT_EQ(view.position.x, 3.0f);
  ASSERT_TRUE(eventually([&] { return link.view().parser.frames >= 4; }));
  const auto acks = link.take_acks();
  ASSERT_EQ(acks.size(), 1u);
  EXPECT_EQ(acks[0].command, mav::cmd_component_arm_disarm);
  EXPECT_TRUE(link.take_acks().empty());

  CommandLong arm;
  arm.command = mav::cmd_component_arm_disarm;
  arm.param1 = 1;
  ASSERT_TRUE(link.send(arm));
  std::array<std::uint8_t, 512> buffer{};
  FrameParser parser;
  const auto frames = parser.feed(std::span(buffer.data(), vehicle.receive(buffer, 1000ms)));
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].system_id, 7) << "a companion speaks as part of its vehicle's system";
  EXPECT_EQ(frames[0].component_id, mav::comp_onboard_computer);
  EXPECT_EQ(frames[0].as<CommandLong>().param1, 1.0f);
}

// The attack of a spoofed heartbeat: an impostor on the same machine claims the autopilot's ids
// from another port. The link stays locked onto the real autopilot's address while its heartbeats
// come, never answers the impostor, and counts what it dropped; after the autopilot has been
// silent longer than the heartbeat timeout, whoever speaks as the autopilot next is pinned.
TEST(MavlinkLink, APinnedPeerIsNotTakenOverByASpoofedHeartbeat) {
  LinkOptions options;
  options.heartbeat_timeout_s = 0.3;
  auto [owned, port] = listening_link(options);
  Link& link = *owned;
  const std::string url = "udpout://127.0.0.1:" + std::to_string(port);
  UdpTransport autopilot(parse_connection_url(url)), impostor(parse_connection_url(url));
  FrameWriter real_ids({1, mav::comp_autopilot1}), spoofed_ids({1, mav::comp_autopilot1});
  Heartbeat hb;
  hb.autopilot = mav::autopilot_px4;
  hb.type = mav::type_quadrotor;
  std::array<std::uint8_t, 512> buffer{};

  EXPECT_FALSE(link.send(Heartbeat{})) << "nobody is answered before the autopilot is heard";
  autopilot.send(real_ids.encode(hb));
  ASSERT_TRUE(eventually([&] { return link.view().peer_pinned; }));
  EXPECT_THAT(link.describe(), ::testing::HasSubstr("(pinned)"));

  for (int i = 0; i < 5; ++i) {
    impostor.send(spoofed_ids.encode(hb));
    autopilot.send(real_ids.encode(hb));
    std::this_thread::sleep_for(20ms);
  }
  ASSERT_TRUE(eventually([&] { return link.view().foreign_datagrams == 5 && link.view().heartbeat_count == 6; }))
      << "only the real autopilot's 6 heartbeats count; " << link.view().heartbeat_count << " counted, "
      << link.view().foreign_datagrams << " dropped";
  ASSERT_TRUE(link.send(CommandLong{}));
  EXPECT_GT(autopilot.receive(buffer, 1000ms), 0u);
  EXPECT_EQ(impostor.receive(buffer, 200ms), 0u) << "the impostor is never answered";

  // The autopilot falls silent: after the timeout the link lets it go, and the next heartbeat pins
  // its sender (here the impostor: without signing, nothing tells them apart).
  std::this_thread::sleep_for(450ms);
  ASSERT_TRUE(eventually([&] { return !link.view().peer_pinned; }));
  impostor.send(spoofed_ids.encode(hb));
  ASSERT_TRUE(eventually([&] { return link.view().peer_pinned && link.view().pins == 2; }));
  ASSERT_TRUE(link.send(CommandLong{}));
  EXPECT_GT(impostor.receive(buffer, 1000ms), 0u);
}

TEST(MavlinkLink, FramesOfOtherSystemsAreIgnoredAndCounted) {
  auto [owned, port] = listening_link();
  Link& link = *owned;
  UdpTransport vehicle(parse_connection_url("udpout://127.0.0.1:" + std::to_string(port)));
  FrameWriter other_vehicle({2, mav::comp_autopilot1});
  Heartbeat hb;
  hb.autopilot = mav::autopilot_px4;
  vehicle.send(other_vehicle.encode(hb));
  LocalPositionNed p;
  p.x = 5.0f;
  vehicle.send(other_vehicle.encode(p));
  ASSERT_TRUE(eventually([&] { return link.view().other_system_frames == 2; }));
  EXPECT_EQ(link.view().heartbeat_count, 0u);
  EXPECT_EQ(link.view().position_count, 0u);
  EXPECT_FALSE(link.view().peer_pinned);
}

// With signing required, the spoofed heartbeat of the attack cannot even pin the link: the
// impostor, first to speak, is dropped as unsigned; one with the wrong key is dropped as badly
// signed; the autopilot's signed heartbeat pins it; a frame the autopilot sent earlier, sent
// again from its own address, is refused as a replay. What the link sends is signed with the key.
TEST(MavlinkLink, RequiredSigningPinsOnlyASignerAndRefusesReplays) {
  SigningKey key{};
  key.fill(0x5A);
  SigningKey wrong_key = key;
  wrong_key[7] = 0;
  LinkOptions options;
  options.signing = std::make_shared<Signing>(SigningMode::require, key, 0);
  auto [owned, port] = listening_link(options);
  Link& link = *owned;
  const std::string url = "udpout://127.0.0.1:" + std::to_string(port);
  UdpTransport autopilot(parse_connection_url(url)), impostor(parse_connection_url(url));
  FrameWriter signed_autopilot({1, mav::comp_autopilot1}, std::make_shared<Signing>(SigningMode::require, key, 0));
  FrameWriter unsigned_impostor({1, mav::comp_autopilot1});
  FrameWriter wrong_key_impostor({1, mav::comp_autopilot1},
                                 std::make_shared<Signing>(SigningMode::require, wrong_key, 0));
  Heartbeat hb;
  hb.autopilot = mav::autopilot_px4;
  hb.type = mav::type_quadrotor;
  std::array<std::uint8_t, 512> buffer{};

  impostor.send(unsigned_impostor.encode(hb));
  impostor.send(wrong_key_impostor.encode(hb));
  ASSERT_TRUE(eventually([&] {
    const SigningCounts c = link.view().signatures;
    return c.unsigned_frames == 1 && c.bad_signature == 1;
  }));
  EXPECT_FALSE(link.view().peer_pinned) << "no frame that fails its signature pins the link";
  EXPECT_EQ(link.view().heartbeat_count, 0u);
  EXPECT_FALSE(link.send(Heartbeat{}));

  const std::vector<std::uint8_t> captured = signed_autopilot.encode(hb);
  autopilot.send(captured);
  ASSERT_TRUE(eventually([&] { return link.view().peer_pinned && link.view().heartbeat_count == 1; }));
  autopilot.send(signed_autopilot.encode(hb));
  ASSERT_TRUE(eventually([&] { return link.view().heartbeat_count == 2; }));
  autopilot.send(captured);
  ASSERT_TRUE(eventually([&] { return link.view().signatures.replayed == 1; }));
  EXPECT_EQ(link.view().heartbeat_count, 2u) << "the replayed heartbeat is not taken";
  EXPECT_EQ(link.view().signatures.signed_frames, 2u);
  // From another address once the link is pinned: dropped as foreign, and still judged, so that
  // the report says what was tried.
  impostor.send(captured);
  impostor.send(unsigned_impostor.encode(hb));
  ASSERT_TRUE(eventually([&] {
    const VehicleView v = link.view();
    return v.foreign_datagrams == 2 && v.signatures.replayed == 2 && v.signatures.unsigned_frames == 2;
  }));
  EXPECT_EQ(link.view().heartbeat_count, 2u);
  EXPECT_EQ(link.view().signing, SigningMode::require);

  ASSERT_TRUE(link.send(CommandLong{}));
  const std::size_t n = autopilot.receive(buffer, 1000ms);
  FrameParser parser;
  const auto frames = parser.feed(std::span(buffer.data(), n));
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_TRUE(frames[0].is_signed());
  EXPECT_TRUE(signature_matches(frames[0], key));
  EXPECT_FALSE(signature_matches(frames[0], wrong_key));
}

TEST(MavlinkLink, OneUrlIsOneLinkInTheProcess) {
  auto first = Link::open("udpin://127.0.0.1:14987");
  auto second = Link::open("udpin://127.0.0.1:14987");
  EXPECT_EQ(first.get(), second.get());
  EXPECT_THAT(first->describe(), ::testing::HasSubstr("14987"));
  // A second node of the link that asks for other options is told so, not silently overruled.
  LinkOptions signed_options;
  signed_options.signing = std::make_shared<Signing>(SigningMode::require, SigningKey{}, 0);
  EXPECT_THAT([&] { Link::open("udpin://127.0.0.1:14987", signed_options); },
              ::testing::ThrowsMessage<kestrel::Error>(::testing::HasSubstr("every node of one link")));
  LinkOptions other_system;
  other_system.autopilot_system_id = 2;
  EXPECT_THROW(Link::open("udpin://127.0.0.1:14987", other_system), kestrel::Error);
}

TEST(MavlinkLink, AVanishedDeviceIsReportedAndNothingIsSentAfter) {
  int master = -1, slave = -1;
  char name[256];
  ASSERT_EQ(openpty(&master, &slave, name, nullptr, nullptr), 0);
  Link link(open_transport(parse_connection_url(std::string("serial://") + name + ":57600")));
  ::close(master);
  ::close(slave);
  ASSERT_TRUE(eventually([&] { return link.failure().has_value(); }));
  EXPECT_THAT(*link.failure(), ::testing::HasSubstr(name));
  EXPECT_FALSE(link.send(Heartbeat{}));
}
