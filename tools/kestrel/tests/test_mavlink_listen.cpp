// `kestrel mavlink listen` as a user runs it, against a vehicle played by the test over loopback UDP.
#include <gmock/gmock.h>

#include <array>
#include <cstdio>
#include <future>
#include <string>
#include <thread>

#include "kestrel/mavlink/connection_url.hpp"
#include "kestrel/mavlink/frame.hpp"
#include "kestrel/mavlink/messages.hpp"
#include "kestrel/mavlink/udp_transport.hpp"
#include "kestrel/testing/run_command.hpp"
#include "kestrel/testing/udp_ports.hpp"

using namespace kestrel::mavlink;
using namespace std::chrono_literals;
using kestrel::testing::run_command;
using Output = kestrel::testing::CommandOutput;

TEST(MavlinkListen, PrintsEachMessageOnALineOfItsOwnAndTheRates) {
  const std::uint16_t port = kestrel::testing::free_udp_port();
  auto listener = std::async(std::launch::async, [&] {
    return run_command(std::string(KESTREL_CLI) + " mavlink listen udpin://127.0.0.1:" + std::to_string(port) +
                       " --count 4 --duration 20");
  });
  auto vehicle = UdpTransport(parse_connection_url("udpout://127.0.0.1:" + std::to_string(port)));
  FrameWriter px4({1, mav::comp_autopilot1});
  Heartbeat hb;
  hb.type = mav::type_quadrotor;
  hb.autopilot = mav::autopilot_px4;
  hb.base_mode = mav::mode_flag_custom_mode_enabled | mav::mode_flag_safety_armed;
  hb.custom_mode = 6u << 16;  // offboard
  hb.system_status = mav::state_active;
  LocalPositionNed p;
  p.x = 1.5f;
  p.z = -2.0f;
  while (listener.wait_for(50ms) != std::future_status::ready) {
    vehicle.send(px4.encode(hb));
    vehicle.send(px4.encode(p));
  }
  const Output out = listener.get();
  EXPECT_EQ(out.status, 0) << out.text;
  EXPECT_THAT(
      out.text,
      ::testing::HasSubstr(
          "HEARTBEAT type=2 autopilot=12 base_mode=129 custom_mode=393216 system_status=4 mavlink_version=3\n"));
  EXPECT_THAT(out.text, ::testing::HasSubstr("LOCAL_POSITION_NED time_boot_ms=0 x=1.5 y=0 z=-2 vx=0 vy=0 vz=0\n"));
  EXPECT_THAT(out.text, ::testing::ContainsRegex("HEARTBEAT +[0-9]+ +[0-9.]+ Hz"));
}

TEST(MavlinkListen, SilenceAndBadUrlsSayWhy) {
  const Output silent = run_command(std::string(KESTREL_CLI) + " mavlink listen udpin://127.0.0.1:" +
                                    std::to_string(kestrel::testing::free_udp_port()) + " --duration 0.3");
  EXPECT_EQ(silent.status, 1);
  EXPECT_THAT(silent.text, ::testing::HasSubstr("no MAVLink frame received"));
  const Output bad = run_command(std::string(KESTREL_CLI) + " mavlink listen tcp://1.2.3.4:5760");
  EXPECT_EQ(bad.status, 2);
  EXPECT_THAT(bad.text, ::testing::HasSubstr("unknown scheme 'tcp'"));
  const Output missing = run_command(std::string(KESTREL_CLI) + " mavlink listen serial:///dev/ttyKESTREL_NONE:57600");
  EXPECT_EQ(missing.status, 1);
  EXPECT_THAT(missing.text, ::testing::HasSubstr("/dev/ttyKESTREL_NONE"));
  const Output help = run_command(std::string(KESTREL_CLI) + " mavlink --help");
  EXPECT_EQ(help.status, 0);
  EXPECT_THAT(help.text, ::testing::HasSubstr("listen"));
}
