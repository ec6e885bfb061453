// `mavlink_sink` in a realtime graph against a fake PX4 over loopback UDP: the offboard sequence,
// the stream's rate, and the safety rules, seen from the autopilot's side of the link.
#include <gmock/gmock.h>

#include <cmath>

#include "kestrel/runtime/graph.hpp"
#include "kestrel/runtime/run.hpp"
#include "kestrel/testing/fake_px4.hpp"
#include "kestrel/testing/plugins.hpp"
#include "kestrel/testing/udp_ports.hpp"

using namespace kestrel;
using namespace kestrel::mavlink;
using kestrel::testing::FakePx4;

namespace {

RunResult run_sink(const std::string& yaml, double seconds) {
  auto built = build_graph(GraphSource::from_string(yaml, "sink.yaml"), kestrel::testing::built_plugins().registry());
  EXPECT_TRUE(built.graph) << built.diagnostics.str();
  if (!built.graph) return {};
  RunOptions options;
  options.duration_s = seconds;
  return run_graph(*built.graph, kestrel::testing::built_plugins().registry(), options);
}

std::string sink_graph(std::uint16_t port, const std::string& sink_params, const std::string& setpoint_params) {
  return "executor: realtime\nnodes:\n"
         "  - {id: setpoint, type: setpoint_step, params: {rate_hz: 50, " +
         setpoint_params +
         "}}\n"
         "  - {id: link, type: mavlink_sink, params: {connection: 'udpin://127.0.0.1:" +
         std::to_string(port) + "', " + sink_params +
         "}}\n"
         "connections:\n  - {from: setpoint.setpoint, to: link.setpoint}\n";
}

std::vector<double> times_of(const std::vector<FakePx4::Received>& got, bool (*pick)(const Frame&)) {
  std::vector<double> t;
  for (const auto& r : got)
    if (pick(r.frame)) t.push_back(r.t);
  return t;
}

bool is_setpoint(const Frame& f) { return f.is<SetPositionTargetLocalNed>(); }
bool is_mode_request(const Frame& f) {
  return f.is<CommandLong>() && f.as<CommandLong>().command == mav::cmd_do_set_mode;
}
bool is_arm(const Frame& f) {
  return f.is<CommandLong>() && f.as<CommandLong>().command == mav::cmd_component_arm_disarm;
}

}  // namespace

TEST(MavlinkSink, PrestreamsArmsTakesOffboardAndStreamsOnlySafeSetpoints) {
  const std::uint16_t port = kestrel::testing::free_udp_port();
  FakePx4 px4(port);
  // (1, 2, 3) ENU first; NaN from 2.0 s to 2.4 s; at 3 s a step 100 m east, outside the fence.
  const RunResult r = run_sink(
      sink_graph(port, "arm: true",
                 "position_m: [1, 2, 3], fault_at_s: 2.0, fault_for_s: 0.4, step_m: [100, 0, 0], step_at_s: 3.0"),
      4.5);
  ASSERT_EQ(r.outcome, RunOutcome::completed) << (r.errors.empty() ? "" : r.errors.front());
  const auto got = px4.received();
  const auto setpoints = times_of(got, is_setpoint);
  const auto modes = times_of(got, is_mode_request);
  const auto arms = times_of(got, is_arm);
  ASSERT_FALSE(setpoints.empty());
  ASSERT_FALSE(modes.empty());
  ASSERT_FALSE(arms.empty());
  EXPECT_GE(arms.front() - setpoints.front(), 0.95) << "a second of setpoints before anything is asked";
  EXPECT_GE(modes.front(), arms.front()) << "armed first, as `arm: true` says";
  const double rate = static_cast<double>(setpoints.size() - 1) / (setpoints.back() - setpoints.front());
  EXPECT_GE(rate, 20.0);

  bool saw_start = false, saw_fence = false;
  for (const auto& g : got) {
    if (!g.frame.is<SetPositionTargetLocalNed>()) continue;
    const auto sp = g.frame.as<SetPositionTargetLocalNed>();
    ASSERT_TRUE(std::isfinite(sp.x) && std::isfinite(sp.y) && std::isfinite(sp.z) && std::isfinite(sp.yaw))
        << "a non-finite setpoint reached the autopilot at t = " << g.t;
    EXPECT_LE(sp.y, 50.0f + 1e-4f) << "east of the fence";
    saw_start =
        saw_start || (std::abs(sp.x - 2.0f) < 1e-5f && std::abs(sp.y - 1.0f) < 1e-5f && std::abs(sp.z + 3.0f) < 1e-5f);
    saw_fence = saw_fence || std::abs(sp.y - 50.0f) < 1e-4f;
    EXPECT_EQ(sp.coordinate_frame, mav::frame_local_ned);
  }
  EXPECT_TRUE(saw_start) << "ENU (1, 2, 3) is NED (2, 1, -3)";
  EXPECT_TRUE(saw_fence);
  EXPECT_EQ(px4.bad_frames(), 0u);
  std::size_t heartbeats = 0;
  for (const auto& g : got)
    heartbeats += g.frame.is<Heartbeat>() && g.frame.as<Heartbeat>().type == mav::type_onboard_controller;
  EXPECT_GE(heartbeats, 3u);

  const auto& link = r.report.at("link");
  EXPECT_EQ(link.at("phase"), "engaged");
  EXPECT_GE(link.at("setpoint_rate_hz").get<double>(), 20.0);
  EXPECT_GE(link.at("non_finite").get<int>(), 1);
  EXPECT_GE(link.at("holds").get<int>(), 1) << "the NaN window is flown as a hold";
  EXPECT_GE(link.at("fence_clamps").get<int>(), 1);
  EXPECT_EQ(link.at("link_losses"), 0);
}

TEST(MavlinkSink, ALostHeartbeatStopsTheCommandingAndItsReturnStartsOver) {
  const std::uint16_t port = kestrel::testing::free_udp_port();
  FakePx4 px4(port);
  px4.silence(2.5, 4.0);
  const RunResult r = run_sink(sink_graph(port, "heartbeat_timeout_s: 0.8", "position_m: [0, 0, 2]"), 6.5);
  ASSERT_EQ(r.outcome, RunOutcome::completed) << (r.errors.empty() ? "" : r.errors.front());
  const auto setpoints = times_of(px4.received(), is_setpoint);
  const auto modes = times_of(px4.received(), is_mode_request);
  // Its last heartbeat before the silence came at about 2.5 s: from 3.3 s the sink is silent too.
  for (const double t : setpoints) EXPECT_FALSE(t > 3.6 && t < 4.0) << "a setpoint during the lost link, t = " << t;
  ASSERT_FALSE(setpoints.empty());
  EXPECT_GT(setpoints.back(), 5.0) << "streaming again after the autopilot came back";
  ASSERT_GE(modes.size(), 2u) << "offboard asked for again";
  EXPECT_GE(modes.back(), 4.9) << "after a new second of pre-stream";
  EXPECT_EQ(r.report.at("link").at("link_losses"), 1);
}

TEST(MavlinkSink, NoAutopilotIsAnErrorThatSaysSo) {
  const std::uint16_t port = kestrel::testing::free_udp_port();
  const RunResult r = run_sink(sink_graph(port, "connect_timeout_s: 0.5", "position_m: [0, 0, 2]"), 2.0);
  EXPECT_EQ(r.outcome, RunOutcome::failed);
  ASSERT_FALSE(r.errors.empty());
  EXPECT_THAT(r.errors.front(), ::testing::HasSubstr("no heartbeat from the autopilot"));
  EXPECT_THAT(r.errors.front(), ::testing::HasSubstr("link"));
}
