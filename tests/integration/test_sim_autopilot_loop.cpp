// sim_autopilot with kestrel's side of the link in one realtime graph: setpoints through
// mavlink_sink, the simulated vehicle flying them, its state back through mavlink_source (which
// the sink's hold uses); over loopback UDP and over a null-modem pair of pseudo-terminals. And
// graphs/field_intercept.yaml with no autopilot to talk to. (graphs/sitl_intercept.yaml, the
// interception flown through MAVLink: test_sitl_intercept.cpp.)
#include <gmock/gmock.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "kestrel/runtime/graph.hpp"
#include "kestrel/runtime/run.hpp"
#include "kestrel/testing/null_modem.hpp"
#include "kestrel/testing/plugins.hpp"
#include "kestrel/testing/scratch_path.hpp"
#include "kestrel/testing/udp_ports.hpp"

using namespace kestrel;

namespace {

// The companion's link and the vehicle's, each a URL; `setpoint` the setpoint_step's parameters.
std::string loop_graph(const std::string& companion, const std::string& vehicle, const std::string& setpoint) {
  return "executor: realtime\nnodes:\n"
         "  - {id: setpoint, type: setpoint_step, params: {rate_hz: 50, " +
         setpoint +
         "}}\n"
         "  - {id: link, type: mavlink_sink, params: {connection: '" +
         companion +
         "', arm: true}}\n"
         "  - {id: telemetry, type: mavlink_source, params: {connection: '" +
         companion +
         "'}}\n"
         "  - {id: hunter, type: sim_autopilot, params: {connection: '" +
         vehicle +
         "'}}\n"
         "connections:\n  - {from: setpoint.setpoint, to: link.setpoint}\n";
}

double distance_to(const nlohmann::json& p, double x, double y, double z) {
  return std::hypot(p.at("x").get<double>() - x, p.at("y").get<double>() - y, p.at("z").get<double>() - z);
}

void expect_clean_link(const nlohmann::json& report) {
  EXPECT_EQ(report.at("hunter").at("bad_checksum"), 0);
  EXPECT_EQ(report.at("telemetry").at("bad_checksum"), 0);
  EXPECT_GE(report.at("link").at("setpoint_rate_hz").get<double>(), 20.0);
  EXPECT_GE(report.at("hunter").at("setpoint_rate_hz").get<double>(), 20.0) << "as the vehicle received them";
  EXPECT_EQ(report.at("hunter").at("offboard_grants"), 1);
  EXPECT_EQ(report.at("hunter").at("offboard_losses"), 0);
  EXPECT_EQ(report.at("telemetry").at("mode"), "offboard");
  EXPECT_EQ(report.at("telemetry").at("armed"), true);
}

}  // namespace

// Take-off to (1, -0.5, 2) m ENU; from 6 s the setpoints turn to NaN, and the sink holds where
// the vehicle's telemetry says it is: it stays there, so both directions of the frame conversions
// agree with the vehicle's.
TEST(SimAutopilotLoop, FliesTheSinksSetpointsOverUdpAndHoldsWhereItIsWhenTheyTurnBad) {
  const std::string port = std::to_string(kestrel::testing::free_udp_port());
  const RunResult r = kestrel::testing::run_built_graph(
      GraphSource::from_string(loop_graph("udpin://127.0.0.1:" + port, "udpout://127.0.0.1:" + port,
                                          "position_m: [1.0, -0.5, 2.0], yaw_deg: 30, "
                                          "fault_at_s: 6.0, fault_for_s: 100.0"),
                               "loop.yaml"),
      9.0);
  ASSERT_EQ(r.outcome, RunOutcome::completed) << (r.errors.empty() ? "" : r.errors.front());
  expect_clean_link(r.report);
  const auto& hunter = r.report.at("hunter");
  EXPECT_LT(distance_to(hunter.at("final_position_m"), 1.0, -0.5, 2.0), 0.15);
  EXPECT_EQ(hunter.at("touchdowns"), 0);
  EXPECT_GE(hunter.at("flight_time_s").get<double>(), 5.0);
  EXPECT_GE(r.report.at("link").at("non_finite").get<int>(), 1);
  EXPECT_EQ(r.report.at("link").at("holds"), 1);
  EXPECT_GE(r.report.at("link").at("hold_setpoints").get<int>(), 50);
}

TEST(SimAutopilotLoop, FliesOverANullModemPairOfSerialPorts) {
  kestrel::testing::NullModem cable;
  const RunResult r = kestrel::testing::run_built_graph(
      GraphSource::from_string(loop_graph("serial://" + cable.a() + ":921600", "serial://" + cable.b() + ":921600",
                                          "position_m: [0.0, 1.0, 1.5]"),
                               "serial.yaml"),
      7.0);
  ASSERT_EQ(r.outcome, RunOutcome::completed) << (r.errors.empty() ? "" : r.errors.front());
  expect_clean_link(r.report);
  EXPECT_LT(distance_to(r.report.at("hunter").at("final_position_m"), 0.0, 1.0, 1.5), 0.15);
  EXPECT_GT(cable.bytes(), 10000u);
}

TEST(SimAutopilotLoop, ALockstepGraphIsRefusedWithTheReason) {
  const std::string port = std::to_string(kestrel::testing::free_udp_port());
  std::string yaml = loop_graph("udpin://127.0.0.1:" + port, "udpout://127.0.0.1:" + port, "position_m: [0, 0, 1]");
  yaml.replace(yaml.find("executor: realtime"), 18, "executor: lockstep");
  const auto built =
      build_graph(GraphSource::from_string(yaml, "lockstep.yaml"), kestrel::testing::built_plugins().registry());
  EXPECT_FALSE(built.graph);
  EXPECT_THAT(built.diagnostics.str(), ::testing::HasSubstr("(sim_autopilot) needs the realtime executor: it talks "
                                                            "over a real link, but the graph runs lockstep"));
  EXPECT_THAT(built.diagnostics.str(), ::testing::HasSubstr("(mavlink_sink) needs the realtime executor"));
}

// graphs/field_intercept.yaml with nothing at the other end of its link: its camera swapped for
// the simulated one (the test machines have no oCamS either), it runs until the sink's connect
// timeout and stops with exit code 1, saying why and naming the node.
TEST(FieldIntercept, WithoutAnAutopilotSaysNoHeartbeatAndExitsWithOne) {
  const std::filesystem::path dir = kestrel::testing::scratch_path("kestrel-field-intercept");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::filesystem::copy(KESTREL_SOURCE_DIR "/graphs/parts", dir / "parts", std::filesystem::copy_options::recursive);
  std::ifstream in(KESTREL_SOURCE_DIR "/graphs/field_intercept.yaml");
  std::string yaml{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const auto from = yaml.find("  - id: camera\n"), to = yaml.find("  - id: telemetry\n");
  ASSERT_NE(from, std::string::npos);
  ASSERT_NE(to, std::string::npos);
  yaml.replace(from, to - from, "  - {id: camera, type: sim_stereo, params: {hfov_deg: 92.8, fps: 30}}\n");
  std::ofstream(dir / "field_intercept.yaml") << yaml;

  const std::string url = "udpin://127.0.0.1:" + std::to_string(kestrel::testing::free_udp_port());
  const std::string command =
      std::string(KESTREL_CLI) + " run " + (dir / "field_intercept.yaml").string() +
      " --duration 10 --no-progress --set link.connect_timeout_s=1 --set link.connection=" + url +
      " --set telemetry.connection=" + url + " > " + (dir / "out.txt").string() + " 2>&1";
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1);
  std::ifstream out(dir / "out.txt");
  const std::string text{std::istreambuf_iterator<char>(out), std::istreambuf_iterator<char>()};
  EXPECT_THAT(text, ::testing::HasSubstr("no heartbeat from the autopilot on " + url + " in 1 s"));
  EXPECT_THAT(text, ::testing::HasSubstr("link"));
  std::filesystem::remove_all(dir);
}

namespace {

// The loop graph with fire orders at 0.5 s (before the vehicle is armed and in offboard) and at
// 4 s (flying), into the sink.
std::string fire_graph(const std::string& port, const std::string& sink_params, const std::string& vehicle_params) {
  static const bool loaded = kestrel::testing::built_plugins().load(KESTREL_TEST_PLUGIN_DIR "/kestrel_test_nodes.so");
  EXPECT_TRUE(loaded);
  std::string yaml = loop_graph("udpin://127.0.0.1:" + port, "udpout://127.0.0.1:" + port, "position_m: [0, 0, 1.5]");
  const auto replace = [&](const std::string& from, const std::string& to) {
    const auto at = yaml.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) yaml.replace(at, from.size(), to);
  };
  replace("arm: true}", "arm: true, " + sink_params + "}");
  replace("'udpout://127.0.0.1:" + port + "'}", "'udpout://127.0.0.1:" + port + "', " + vehicle_params + "}");
  replace("connections:\n",
          "  - {id: orders, type: fire_orders, params: {first_s: 0.5, second_s: 4.0}}\n"
          "connections:\n  - {from: orders.fire, to: link.fire, policy: fifo 16}\n");
  return yaml;
}

}  // namespace

// The fire order reaches the launcher only when the vehicle is armed, in offboard and the net is
// armed: then as the servo (or relay) command the vehicle's launcher output answers.
TEST(SimAutopilotLoop, AFireOrderReachesTheLauncherOnlyWhenFlyingAndTheNetIsArmed) {
  struct Case {
    std::string sink, vehicle;
    int fired, refused, launched;
  };
  for (const Case& c : {Case{"net_armed: true", "", 1, 1, 1},
                        Case{"net_armed: true, fire_command: relay, fire_channel: 2, fire_value: 1",
                             "launcher: relay, launcher_channel: 2, launcher_threshold: 1", 1, 1, 1},
                        Case{"net_armed: true, fire_channel: 7", "", 1, 1, 0},  // not the launcher's output
                        Case{"net_armed: false", "", 0, 2, 0}}) {
    SCOPED_TRACE(c.sink);
    const std::string port = std::to_string(kestrel::testing::free_udp_port());
    const std::string vehicle = c.vehicle.empty() ? "launcher_channel: 9" : c.vehicle;
    const RunResult r = kestrel::testing::run_built_graph(
        GraphSource::from_string(fire_graph(port, c.sink, vehicle), "fire.yaml"), 5.0);
    ASSERT_EQ(r.outcome, RunOutcome::completed) << (r.errors.empty() ? "" : r.errors.front());
    EXPECT_EQ(r.report.at("link").at("fired"), c.fired);
    EXPECT_EQ(r.report.at("link").at("fire_refused"), c.refused);
    EXPECT_EQ(r.report.at("hunter").at("fire_orders"), c.launched);
  }
}
