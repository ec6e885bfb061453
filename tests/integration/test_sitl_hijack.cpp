// The hijack of graphs/sitl_intercept.yaml's link, as an attacker on the companion computer's
// network would try it (docs/field.md, "Security"): from 3 s on, an impostor on this machine sends
// MAVLink 2 heartbeats to kestrel's udpin port from a port of its own, claiming the autopilot's
// system and component ids (1, 1). Without defences, kestrel's link answers the last sender: it
// streams its setpoints to the impostor and the real vehicle leaves offboard. Each mode below
// runs the graph with that attack and checks what the impostor got and what the vehicle did.
// The attack stops a second and a half before the run ends: once the run stops, the autopilot is
// silent, the link lets it go after its heartbeat timeout, and the next heartbeat from anyone
// would be pinned, as a rebooted autopilot's must be.
#include <gmock/gmock.h>

#include <atomic>
#include <fstream>
#include <thread>

#include "kestrel/mavlink/connection_url.hpp"
#include "kestrel/mavlink/messages.hpp"
#include "kestrel/mavlink/signing.hpp"
#include "kestrel/mavlink/udp_transport.hpp"
#include "kestrel/testing/plugins.hpp"
#include "kestrel/testing/scratch_path.hpp"
#include "kestrel/testing/udp_ports.hpp"

using namespace kestrel;
using namespace std::chrono_literals;

namespace {

enum class Attack {
  unpinned,  // the old link (pin_peer: false, no signing): the attack must be seen to work
  pinned,    // the link pinned to the autopilot's address, unsigned
  signed_,   // signing required on both ends; the impostor's heartbeats are unsigned
  replayed,  // signing required; the impostor replays a signed heartbeat the autopilot sent earlier
};

struct Impostor {
  std::uint64_t sent = 0;
  std::uint64_t bytes_received = 0;
};

constexpr double kRunS = 8.0, kAttackFromS = 3.0, kAttackUntilS = 6.5;

mavlink::Heartbeat autopilot_heartbeat() {
  mavlink::Heartbeat hb;
  hb.type = mavlink::mav::type_quadrotor;
  hb.autopilot = mavlink::mav::autopilot_px4;
  hb.base_mode = mavlink::mav::mode_flag_custom_mode_enabled | mavlink::mav::mode_flag_safety_armed;
  hb.custom_mode = 6u << 16;  // offboard
  hb.system_status = mavlink::mav::state_active;
  return hb;
}

class SitlHijack : public ::testing::TestWithParam<Attack> {};

}  // namespace

TEST_P(SitlHijack, TheImpostorGetsNothingAndTheVehicleStaysInOffboard) {
  const Attack attack = GetParam();
  const std::uint16_t port = kestrel::testing::free_udp_port();
  std::vector<std::string> sets = {"link.connection=udpin://127.0.0.1:" + std::to_string(port),
                                   "telemetry.connection=udpin://127.0.0.1:" + std::to_string(port),
                                   "hunter.connection=udpout://127.0.0.1:" + std::to_string(port)};
  if (attack == Attack::unpinned) {
    sets.push_back("link.pin_peer=false");
    sets.push_back("telemetry.pin_peer=false");
  }
  const bool signing = attack == Attack::signed_ || attack == Attack::replayed;
  const std::string key_file = kestrel::testing::scratch_path("hijack.key").string();
  std::filesystem::remove(key_file);
  const mavlink::SigningKey key = mavlink::random_signing_key();
  if (signing) {
    mavlink::write_signing_key(key_file, key);
    for (const char* node : {"link", "telemetry", "hunter"}) {
      sets.push_back(std::string(node) + ".signing=require");
      sets.push_back(std::string(node) + ".signing_key_file=" + key_file);
    }
  }
  // What the autopilot sent before the attack, as an eavesdropper would have kept it: a heartbeat
  // signed with the real key by the autopilot's own ids and link id (0), timestamped now.
  mavlink::FrameWriter recorded({1, mavlink::mav::comp_autopilot1},
                                std::make_shared<mavlink::Signing>(mavlink::SigningMode::require, key, 0));
  const std::vector<std::uint8_t> captured = recorded.encode(autopilot_heartbeat());

  // The attack's clock starts when the run is under way, not when this test starts: loading the
  // plugins and building the graph can take seconds (under a sanitizer), and an impostor heard
  // before the real autopilot is the first peer, which no pinning can tell apart.
  Impostor impostor;
  std::atomic<bool> stop{false}, running{false};
  std::thread attacker([&] {
    mavlink::UdpTransport socket(mavlink::parse_connection_url("udpout://127.0.0.1:" + std::to_string(port)));
    mavlink::FrameWriter spoofed({1, mavlink::mav::comp_autopilot1});
    std::array<std::uint8_t, 2048> buffer{};
    while (!stop && !running) std::this_thread::sleep_for(5ms);
    const auto start = std::chrono::steady_clock::now();
    while (!stop) {
      const std::chrono::duration<double> since = std::chrono::steady_clock::now() - start;
      if (since.count() >= kAttackFromS && since.count() < kAttackUntilS) {
        socket.send(attack == Attack::replayed ? captured : spoofed.encode(autopilot_heartbeat()));
        ++impostor.sent;
      }
      impostor.bytes_received += socket.receive(buffer, 50ms);
    }
  });
  auto built = build_graph(GraphSource::from_file(KESTREL_SOURCE_DIR "/graphs/sitl_intercept.yaml"),
                           kestrel::testing::built_plugins().registry(), sets);
  RunResult r;
  if (built.graph) {
    RunOptions options;
    options.duration_s = kRunS;
    options.seed = 1;
    options.on_running = [&] { running = true; };
    r = run_graph(*built.graph, kestrel::testing::built_plugins().registry(), options);
  }
  stop = true;
  attacker.join();
  std::filesystem::remove(key_file);

  ASSERT_TRUE(built.graph) << built.diagnostics.str();
  ASSERT_EQ(r.outcome, RunOutcome::completed) << (r.errors.empty() ? "" : r.errors.front());
  const auto& link = r.report.at("link");
  const auto& hunter = r.report.at("hunter");
  ASSERT_GE(impostor.sent, 40u) << "the attack ran for 3.5 s of the run";
  if (attack == Attack::unpinned) {
    // The defences off: the link answers the impostor, as in the attack that was reported.
    EXPECT_GT(impostor.bytes_received, 0u) << "without pinning or signing the impostor is answered";
    return;
  }
  EXPECT_EQ(impostor.bytes_received, 0u) << "the impostor is never answered";
  EXPECT_EQ(hunter.at("offboard_grants"), 1);
  EXPECT_EQ(hunter.at("offboard_losses"), 0) << "the vehicle never left offboard";
  EXPECT_EQ(hunter.at("mode"), "offboard");
  EXPECT_EQ(link.at("releases"), 0);
  EXPECT_EQ(link.at("fire_refused"), 0);
  EXPECT_EQ(link.at("peer_pins"), 1) << "pinned once, to the real autopilot";
  // Every datagram of the impostor reached the link while the autopilot spoke, and was dropped as
  // foreign.
  EXPECT_EQ(link.at("foreign_datagrams").get<std::uint64_t>(), impostor.sent);
  if (attack == Attack::signed_) {
    EXPECT_EQ(link.at("unsigned_frames"), link.at("foreign_datagrams")) << "each spoofed heartbeat: unsigned";
    EXPECT_EQ(link.at("replayed_frames"), 0);
  }
  if (attack == Attack::replayed) {
    EXPECT_EQ(link.at("replayed_frames"), link.at("foreign_datagrams")) << "each copy: a replay";
    EXPECT_EQ(link.at("unsigned_frames"), 0);
  }
  if (signing) {
    EXPECT_EQ(link.at("bad_signature"), 0);
    EXPECT_GT(link.at("signed_frames").get<std::uint64_t>(), 100u) << "the autopilot's frames, all signed";
    EXPECT_EQ(hunter.at("unsigned_frames"), 0) << "everything the link sent was signed";
    EXPECT_GT(hunter.at("signed_frames").get<std::uint64_t>(), 100u);
  }
}

INSTANTIATE_TEST_SUITE_P(Attacks, SitlHijack,
                         ::testing::Values(Attack::unpinned, Attack::pinned, Attack::signed_, Attack::replayed),
                         [](const ::testing::TestParamInfo<Attack>& info) {
                           switch (info.param) {
                             case Attack::unpinned:
                               return std::string("Unpinned");
                             case Attack::pinned:
                               return std::string("Pinned");
                             case Attack::signed_:
                               return std::string("Signed");
                             case Attack::replayed:
                               return std::string("Replayed");
                           }
                           return std::string("Unknown");
                         });
