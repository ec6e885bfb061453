// `kestrel mavlink keygen` and `kestrel mavlink setup-signing` as a user runs them, the autopilot
// played by the test over loopback UDP: it hears SETUP_SIGNING and signs with the key it got (as
// PX4 and ArduPilot do), or ignores it (an autopilot that takes the key only over USB).
#include <gmock/gmock.h>
#include <sys/stat.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <future>
#include <string>

#include "kestrel/mavlink/connection_url.hpp"
#include "kestrel/mavlink/frame_parser.hpp"
#include "kestrel/mavlink/messages.hpp"
#include "kestrel/mavlink/signing.hpp"
#include "kestrel/mavlink/udp_transport.hpp"
#include "kestrel/testing/run_command.hpp"
#include "kestrel/testing/scratch_path.hpp"
#include "kestrel/testing/udp_ports.hpp"

using namespace kestrel::mavlink;
using namespace std::chrono_literals;
using kestrel::testing::run_command;
using Output = kestrel::testing::CommandOutput;

namespace {

std::string fresh_path(const std::string& name) {
  const std::string path = kestrel::testing::scratch_path(name).string();
  std::filesystem::remove(path);
  return path;
}

// An autopilot on a udpin port: heartbeats every 50 ms to whoever spoke, SETUP_SIGNING taken when
// `accept_key`. Runs until `done` is ready; returns the key it was given (if any).
std::optional<SigningKey> play_autopilot(UdpTransport& socket, bool accept_key, std::future<Output>& done) {
  FrameParser parser;
  FrameWriter unsigned_writer({1, mav::comp_autopilot1});
  std::unique_ptr<FrameWriter> signed_writer;
  std::optional<SigningKey> given;
  Heartbeat hb;
  hb.type = mav::type_quadrotor;
  hb.autopilot = mav::autopilot_px4;
  std::array<std::uint8_t, 2048> buffer{};
  while (done.wait_for(0ms) != std::future_status::ready) {
    const std::size_t n = socket.receive(buffer, 50ms);
    for (const Frame& f : parser.feed(std::span(buffer.data(), n))) {
      if (!f.is<SetupSigning>() || !accept_key) continue;
      const SetupSigning s = f.as<SetupSigning>();
      if (s.target_system != 1 || s.target_component != mav::comp_autopilot1) continue;
      given = s.secret_key;
      signed_writer = std::make_unique<FrameWriter>(Sender{1, mav::comp_autopilot1},
                                                    std::make_shared<Signing>(SigningMode::require, s.secret_key, 0));
    }
    socket.send(signed_writer ? signed_writer->encode(hb) : unsigned_writer.encode(hb));
  }
  return given;
}

}  // namespace

TEST(MavlinkSigningCommands, KeygenWritesAKeyForItsOwnerOnlyAndNeverOverwritesOne) {
  const std::string key = fresh_path("keygen.key");
  const Output first = run_command(std::string(KESTREL_CLI) + " mavlink keygen " + key);
  ASSERT_EQ(first.status, 0) << first.text;
  struct stat st {};
  ASSERT_EQ(::stat(key.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0600u);
  const SigningKey written = load_signing_key(key);
  EXPECT_THAT(first.text, ::testing::Not(::testing::HasSubstr(to_hex(written)))) << "a secret is never printed";
  const Output again = run_command(std::string(KESTREL_CLI) + " mavlink keygen " + key);
  EXPECT_EQ(again.status, 1);
  EXPECT_THAT(again.text, ::testing::HasSubstr("never overwritten"));
  EXPECT_EQ(load_signing_key(key), written);
  EXPECT_EQ(run_command(std::string(KESTREL_CLI) + " mavlink keygen").status, 2);
  std::filesystem::remove(key);
}

TEST(MavlinkSigningCommands, SetupSigningHandsTheKeyOverAndSeesTheAutopilotSignWithIt) {
  const std::string key = fresh_path("setup.key");
  ASSERT_EQ(run_command(std::string(KESTREL_CLI) + " mavlink keygen " + key).status, 0);
  auto socket = kestrel::testing::listening_udp();
  const std::uint16_t port = socket->local_port();
  auto command = std::async(std::launch::async, [&] {
    return run_command(std::string(KESTREL_CLI) + " mavlink setup-signing udpout://127.0.0.1:" + std::to_string(port) +
                       " --key " + key + " --timeout 10");
  });
  const std::optional<SigningKey> given = play_autopilot(*socket, true, command);
  const Output out = command.get();
  EXPECT_EQ(out.status, 0) << out.text;
  EXPECT_THAT(out.text, ::testing::HasSubstr("sending SETUP_SIGNING to system 1 component 1"));
  EXPECT_THAT(out.text, ::testing::HasSubstr("signs with this key"));
  ASSERT_TRUE(given.has_value());
  EXPECT_EQ(*given, load_signing_key(key));
  std::filesystem::remove(key);
}

TEST(MavlinkSigningCommands, SetupSigningSaysSoWhenTheAutopilotNeverSigns) {
  const std::string key = fresh_path("ignored.key");
  ASSERT_EQ(run_command(std::string(KESTREL_CLI) + " mavlink keygen " + key).status, 0);
  auto socket = kestrel::testing::listening_udp();
  const std::uint16_t port = socket->local_port();
  auto command = std::async(std::launch::async, [&] {
    return run_command(std::string(KESTREL_CLI) + " mavlink setup-signing udpout://127.0.0.1:" + std::to_string(port) +
                       " --key " + key + " --timeout 1.5");
  });
  EXPECT_FALSE(play_autopilot(*socket, false, command).has_value());
  const Output out = command.get();
  EXPECT_EQ(out.status, 1) << out.text;
  EXPECT_THAT(out.text, ::testing::HasSubstr("no frame of system 1 came signed with this key"));

  // A key file open to others is refused before anything is sent; a bad URL is a usage error.
  ::chmod(key.c_str(), 0644);
  const Output exposed = run_command(std::string(KESTREL_CLI) + " mavlink setup-signing udpout://127.0.0.1:9 --key " +
                                     key + " --timeout 0.2");
  EXPECT_EQ(exposed.status, 1);
  EXPECT_THAT(exposed.text, ::testing::HasSubstr("chmod 600"));
  const Output bad_url = run_command(std::string(KESTREL_CLI) + " mavlink setup-signing tcp://1.2.3.4:5 --key " + key);
  EXPECT_EQ(bad_url.status, 2);
  std::filesystem::remove(key);
}
