// `mavlink_source` in a realtime graph, against a PX4 vehicle played by the test over loopback
// UDP: it reads the vehicle's state and status, and counts the link's loss when the heartbeats stop.
#include <gmock/gmock.h>

#include <atomic>
#include <thread>

#include "kestrel/mavlink/connection_url.hpp"
#include "kestrel/mavlink/frame.hpp"
#include "kestrel/mavlink/messages.hpp"
#include "kestrel/mavlink/udp_transport.hpp"
#include "kestrel/runtime/graph.hpp"
#include "kestrel/runtime/run.hpp"
#include "kestrel/testing/plugins.hpp"
#include "kestrel/testing/udp_ports.hpp"

using namespace kestrel;
using namespace kestrel::mavlink;
using namespace std::chrono_literals;

namespace {

// A PX4 vehicle in offboard, armed, 5 m up, sending at 50 Hz, its heartbeat at 2 Hz until `silent_after`.
void fly(std::uint16_t port, std::atomic<bool>& stop, std::chrono::milliseconds silent_after) {
  UdpTransport link(parse_connection_url("udpout://127.0.0.1:" + std::to_string(port)));
  FrameWriter px4({1, mav::comp_autopilot1});
  Heartbeat hb;
  hb.type = mav::type_quadrotor;
  hb.autopilot = mav::autopilot_px4;
  hb.base_mode = mav::mode_flag_custom_mode_enabled | mav::mode_flag_safety_armed;
  hb.custom_mode = 6u << 16;
  hb.system_status = mav::state_active;
  LocalPositionNed p;
  p.z = -5;
  const AttitudeQuaternion a;
  const auto start = std::chrono::steady_clock::now();
  for (int k = 0; !stop; ++k) {
    if (k % 25 == 0 && std::chrono::steady_clock::now() - start < silent_after) link.send(px4.encode(hb));
    link.send(px4.encode(p));
    link.send(px4.encode(a));
    std::this_thread::sleep_for(20ms);
  }
}

// Runs mavlink_source for `seconds` with `vehicle` flying beside it. The graph is built first, so
// that the node's socket is open within moments of the vehicle's first message.
RunResult run_source(std::uint16_t port, double seconds, std::chrono::milliseconds silent_after) {
  const auto graph = GraphSource::from_string(
      "executor: realtime\nnodes:\n  - {id: link, type: mavlink_source, params: {connection: 'udpin://127.0.0.1:" +
          std::to_string(port) + "', heartbeat_timeout_s: 0.8}}\n",
      "mavlink_source.yaml");
  auto built = build_graph(graph, kestrel::testing::built_plugins().registry());
  EXPECT_TRUE(built.graph) << built.diagnostics.str();
  if (!built.graph) return {};
  RunOptions options;
  options.duration_s = seconds;
  std::atomic<bool> stop{false};
  std::thread vehicle(fly, port, std::ref(stop), silent_after);
  RunResult r = run_graph(*built.graph, kestrel::testing::built_plugins().registry(), options);
  stop = true;
  vehicle.join();
  return r;
}

}  // namespace

TEST(MavlinkSource, ReadsTheVehiclesStateAndStatus) {
  const RunResult r = run_source(kestrel::testing::free_udp_port(), 1.5, 1h);
  ASSERT_EQ(r.outcome, RunOutcome::completed) << (r.errors.empty() ? "" : r.errors.front());
  const auto& link = r.report.at("link");
  EXPECT_GT(link.at("states").get<int>(), 30);
  EXPECT_GE(link.at("heartbeats").get<int>(), 2);
  EXPECT_EQ(link.at("mode"), "offboard");
  EXPECT_EQ(link.at("autopilot"), "px4");
  EXPECT_EQ(link.at("armed"), true);
  EXPECT_EQ(link.at("bad_checksum"), 0);
  EXPECT_EQ(link.at("link_losses"), 0);
}

TEST(MavlinkSource, CountsTheLinkLostWhenHeartbeatsStop) {
  const RunResult r = run_source(kestrel::testing::free_udp_port(), 2.5, 600ms);
  ASSERT_EQ(r.outcome, RunOutcome::completed) << (r.errors.empty() ? "" : r.errors.front());
  EXPECT_EQ(r.report.at("link").at("link_losses"), 1);
}

// A real link needs the realtime executor: a lockstep graph is refused when it is built, at the
// node's type; a host that switches the executor afterwards gets a node that does not start.
TEST(MavlinkSource, RefusesTheLockstepExecutor) {
  const auto graph = GraphSource::from_string(
      "nodes:\n  - {id: link, type: mavlink_source, params: {connection: 'udpin://127.0.0.1:14988'}}\n",
      "lockstep.yaml");
  auto& registry = kestrel::testing::built_plugins().registry();
  const auto refused = build_graph(graph, registry);
  EXPECT_FALSE(refused.graph);
  EXPECT_THAT(refused.diagnostics.str(),
              ::testing::HasSubstr("lockstep.yaml:2:22: error: node 'link' (mavlink_source) needs the realtime "
                                   "executor: it talks to a real link, but the graph runs lockstep"));
  auto built = build_graph(graph, registry, {}, {}, ExecutorKind::realtime);
  ASSERT_TRUE(built.graph) << built.diagnostics.str();
  built.graph->executor = ExecutorKind::lockstep;
  built.graph->clock = ClockKind::simulated;
  RunOptions options;
  options.duration_s = 0.1;
  const RunResult r = run_graph(*built.graph, registry, options);
  EXPECT_EQ(r.outcome, RunOutcome::failed);
  ASSERT_FALSE(r.errors.empty());
  EXPECT_THAT(r.errors.front(), ::testing::HasSubstr("needs the realtime executor"));
}
