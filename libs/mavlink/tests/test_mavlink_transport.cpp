// The transports a connection URL names, over what a test can own: loopback UDP sockets and a
// pseudo-terminal pair.
#include <gmock/gmock.h>
#include <pty.h>
#include <unistd.h>

#include <array>
#include <kestrel/error.hpp>

#include "kestrel/mavlink/connection_url.hpp"
#include "kestrel/mavlink/frame.hpp"
#include "kestrel/mavlink/frame_parser.hpp"
#include "kestrel/mavlink/messages.hpp"
#include "kestrel/mavlink/transport.hpp"
#include "kestrel/mavlink/udp_transport.hpp"
#include "kestrel/testing/udp_ports.hpp"

using namespace kestrel;
using namespace kestrel::mavlink;
using namespace std::chrono_literals;
using ::testing::HasSubstr;

TEST(MavlinkConnectionUrl, ReadsMavsdksThreeForms) {
  const auto in = parse_connection_url("udpin://0.0.0.0:14540");
  EXPECT_EQ(in.kind, ConnectionUrl::Kind::udp_in);
  EXPECT_EQ(in.host, "0.0.0.0");
  EXPECT_EQ(in.port, 14540);
  const auto out = parse_connection_url("udpout://127.0.0.1:14550");
  EXPECT_EQ(out.kind, ConnectionUrl::Kind::udp_out);
  EXPECT_EQ(out.host, "127.0.0.1");
  EXPECT_EQ(out.port, 14550);
  const auto serial = parse_connection_url("serial:///dev/ttyACM0:921600");
  EXPECT_EQ(serial.kind, ConnectionUrl::Kind::serial);
  EXPECT_EQ(serial.device, "/dev/ttyACM0");
  EXPECT_EQ(serial.baud, 921600);
  EXPECT_EQ(parse_connection_url("serial:///dev/ttyUSB0").baud, 57600);
  EXPECT_EQ(parse_connection_url("udpin://:14540").host, "0.0.0.0");
}

TEST(MavlinkConnectionUrl, SaysWhatIsWrongWithABadOne) {
  const auto refusal = [](const std::string& url) {
    try {
      parse_connection_url(url);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_THAT(refusal("14540"), HasSubstr("no scheme"));
  EXPECT_THAT(refusal("tcp://1.2.3.4:5760"), HasSubstr("unknown scheme 'tcp'"));
  EXPECT_THAT(refusal("udpin://0.0.0.0"), HasSubstr("no port"));
  EXPECT_THAT(refusal("udpin://0.0.0.0:99999"), HasSubstr("is not a port"));
  EXPECT_THAT(refusal("udpout://:14540"), HasSubstr("needs the host"));
  EXPECT_THAT(refusal("serial://ttyACM0:57600"), HasSubstr("must be a path"));
  EXPECT_THAT(refusal("serial:///dev/ttyACM0:12345"), HasSubstr("not a baud rate"));
  EXPECT_THAT(refusal("serial:///dev/ttyACM0:fast"), HasSubstr("'fast' is not a baud rate"));
  EXPECT_THAT(refusal("udpin://0.0.0.0:x"), HasSubstr("udpin://HOST:PORT, udpout://HOST:PORT or serial://"));
}

TEST(MavlinkUdp, UdpinAnswersWhoeverSpokeLastAndUdpoutHearsTheReply) {
  auto listening = kestrel::testing::listening_udp();
  UdpTransport& listener = *listening;
  const std::array<std::uint8_t, 3> hello = {1, 2, 3};
  EXPECT_FALSE(listener.send(hello)) << "nobody has spoken yet";

  auto sender = open_transport(parse_connection_url("udpout://127.0.0.1:" + std::to_string(listener.local_port())));
  FrameWriter vehicle({1, 1});
  ASSERT_TRUE(sender->send(vehicle.encode(Heartbeat{})));
  std::array<std::uint8_t, 512> buffer{};
  const std::size_t n = listener.receive(buffer, 1000ms);
  FrameParser parser;
  const auto frames = parser.feed(std::span(buffer.data(), n));
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_TRUE(frames[0].is<Heartbeat>());
  EXPECT_THAT(listener.describe(), HasSubstr("peer 127.0.0.1:"));

  FrameWriter companion({1, mav::comp_onboard_computer});
  ASSERT_TRUE(listener.send(companion.encode(ExtendedSysState{})));
  const std::size_t m = sender->receive(buffer, 1000ms);
  const auto reply = parser.feed(std::span(buffer.data(), m));
  ASSERT_EQ(reply.size(), 1u);
  EXPECT_EQ(reply[0].component_id, mav::comp_onboard_computer);
  EXPECT_EQ(sender->receive(buffer, 20ms), 0u) << "nothing more came";
}

TEST(MavlinkUdp, APortTakenIsRefusedWithItsName) {
  const auto first = kestrel::testing::listening_udp();
  const std::string taken = "udpin://127.0.0.1:" + std::to_string(first->local_port());
  try {
    open_transport(parse_connection_url(taken));
    FAIL() << "a second socket bound the same port";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr(taken));
    EXPECT_THAT(e.what(), HasSubstr("in use"));
  }
}

TEST(MavlinkSerial, FramesCrossAPseudoTerminalBothWaysAndAHangUpIsNamed) {
  int master = -1, slave = -1;
  char name[256];
  ASSERT_EQ(openpty(&master, &slave, name, nullptr, nullptr), 0);
  auto port = open_transport(parse_connection_url(std::string("serial://") + name + ":921600"));
  EXPECT_THAT(port->describe(), HasSubstr("at 921600"));

  FrameWriter vehicle({1, 1});
  LocalPositionNed p;
  p.z = -10.0f;
  const auto frame = vehicle.encode(p);
  // Split in two writes, as a UART delivers it.
  ASSERT_EQ(::write(master, frame.data(), 7), 7);
  ASSERT_EQ(::write(master, frame.data() + 7, frame.size() - 7), static_cast<ssize_t>(frame.size() - 7));
  FrameParser parser;
  std::vector<Frame> got;
  std::array<std::uint8_t, 256> buffer{};
  for (int i = 0; i < 20 && got.empty(); ++i) got = parser.feed(std::span(buffer.data(), port->receive(buffer, 100ms)));
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].as<LocalPositionNed>().z, -10.0f);

  FrameWriter companion({1, mav::comp_onboard_computer});
  const auto reply = companion.encode(Heartbeat{});
  ASSERT_TRUE(port->send(reply));
  std::array<std::uint8_t, 64> echoed{};
  std::size_t have = 0;
  for (int i = 0; i < 50 && have < reply.size(); ++i) {
    const ssize_t n = ::read(master, echoed.data() + have, echoed.size() - have);
    if (n > 0) have += static_cast<std::size_t>(n);
  }
  EXPECT_EQ(std::vector<std::uint8_t>(echoed.begin(), echoed.begin() + static_cast<std::ptrdiff_t>(have)), reply);

  ::close(master);
  ::close(slave);
  try {
    for (int i = 0; i < 10; ++i) port->receive(buffer, 50ms);
    FAIL() << "a hung-up port read as a quiet one";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr(name));
  }
}

TEST(MavlinkSerial, AMissingPortIsNamed) {
  try {
    open_transport(parse_connection_url("serial:///dev/ttyKESTREL_NONE:57600"));
    FAIL();
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("/dev/ttyKESTREL_NONE"));
  }
}
