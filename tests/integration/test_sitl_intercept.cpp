// graphs/sitl_intercept.yaml, the interception flown through MAVLink by sim_autopilot, on the
// seeds of the closed-loop test (ClosedLoop.*). Realtime with the rendered camera: its tests run
// alone (RUN_SERIAL), so that other tests do not take the cores the camera needs for 30 FPS.
#include <gmock/gmock.h>

#include "kestrel/testing/plugins.hpp"
#include "kestrel/testing/udp_ports.hpp"

using namespace kestrel;

// The interception through MAVLink, on the seeds of the closed-loop test (ClosedLoop.*): it
// captures, with setpoints at 20 Hz or more and not one frame with a bad checksum either way,
// and the fire order travels the whole chain (aim -> sink -> vehicle's launcher output -> net).
class SitlIntercept : public ::testing::TestWithParam<std::uint64_t> {};

TEST_P(SitlIntercept, CapturesWithACleanLink) {
  const std::string port = std::to_string(kestrel::testing::free_udp_port());
  const RunResult r = kestrel::testing::run_built_graph(
      GraphSource::from_file(KESTREL_SOURCE_DIR "/graphs/sitl_intercept.yaml"), 15.0,
      {"link.connection=udpin://127.0.0.1:" + port, "telemetry.connection=udpin://127.0.0.1:" + port,
       "hunter.connection=udpout://127.0.0.1:" + port},
      GetParam());
  ASSERT_EQ(r.outcome, RunOutcome::completed) << (r.errors.empty() ? "" : r.errors.front());
  const auto& report = r.report;
  EXPECT_EQ(report.at("control").at("captured"), true);
  EXPECT_GE(report.at("link").at("fired").get<int>(), 1);
  EXPECT_GE(report.at("hunter").at("fire_orders").get<int>(), 1);
  EXPECT_EQ(report.at("hunter").at("touchdowns"), 0);
  EXPECT_EQ(report.at("link").at("non_finite"), 0);
  EXPECT_EQ(report.at("hunter").at("bad_checksum"), 0);
  EXPECT_EQ(report.at("telemetry").at("bad_checksum"), 0);
  EXPECT_GE(report.at("link").at("setpoint_rate_hz").get<double>(), 20.0);
  EXPECT_GE(report.at("hunter").at("setpoint_rate_hz").get<double>(), 20.0);
  EXPECT_EQ(report.at("hunter").at("offboard_grants"), 1);
}

INSTANTIATE_TEST_SUITE_P(ClosedLoopSeeds, SitlIntercept, ::testing::Values(1u, 3u));
