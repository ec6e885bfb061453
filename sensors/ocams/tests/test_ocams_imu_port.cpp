// The IMU driver against a pseudo-terminal pair: a test thread plays the device's side, a session
// with corrupt lines and a reply, then hangs up; a new device appears behind the same name, and
// the stream reopens it.
#include <fcntl.h>
#include <gmock/gmock.h>
#include <pty.h>
#include <unistd.h>

#include <filesystem>
#include <thread>

#include "imu_protocol.hpp"
#include "imu_stream.hpp"
#include "kestrel/testing/scratch_path.hpp"
#include "kestrel/testing/steady_now.hpp"

using namespace kestrel;
using namespace kestrel::ocams;
using namespace std::chrono_literals;
using kestrel::testing::steady_now;

namespace {

// A pseudo-terminal whose slave the driver opens through a stable symlink, as udev names the IMU.
struct FakeImuPort {
  int master = -1, slave = -1;
  explicit FakeImuPort(const std::filesystem::path& link) {
    char name[256];
    if (openpty(&master, &slave, name, nullptr, nullptr) != 0) throw std::runtime_error("openpty");
    std::filesystem::remove(link);
    std::filesystem::create_symlink(name, link);
  }
  ~FakeImuPort() { hang_up(); }
  void send(const std::string& line) {
    const std::string s = line + "\r\n";
    ASSERT_EQ(::write(master, s.data(), s.size()), static_cast<ssize_t>(s.size()));
  }
  std::string received(std::chrono::milliseconds wait) {
    std::string out;
    const auto end = std::chrono::steady_clock::now() + wait;
    fcntl(master, F_SETFL, O_NONBLOCK);
    while (std::chrono::steady_clock::now() < end) {
      char b[128];
      const ssize_t n = ::read(master, b, sizeof b);
      if (n > 0) out.append(b, static_cast<std::size_t>(n));
      if (out.find('\n') != std::string::npos) break;
      std::this_thread::sleep_for(5ms);
    }
    return out;
  }
  void hang_up() {
    if (master >= 0) ::close(master);
    if (slave >= 0) ::close(slave);
    master = slave = -1;
  }
};

std::filesystem::path link_path() {
  const auto dir = kestrel::testing::scratch_path("kestrel-imu-port");
  std::filesystem::create_directories(dir);
  return dir / "ttyOCAMS";
}

std::vector<msg::Imu> read_for(ImuStream& s, std::chrono::milliseconds total) {
  std::vector<msg::Imu> out;
  const auto end = std::chrono::steady_clock::now() + total;
  while (std::chrono::steady_clock::now() < end)
    for (auto& m : s.read(20ms)) out.push_back(m);
  return out;
}

}  // namespace

TEST(OcamsImuPort, ASessionWithCorruptLinesGivesEveryGoodSampleAndCountsTheRest) {
  const auto link = link_path();
  FakeImuPort device(link);
  ImuStreamOptions o;
  o.port = link.string();
  o.silence_timeout = 2s;
  ImuStream stream(o, steady_now);
  EXPECT_EQ(device.received(500ms), "@AMGQUA\r\n");  // the driver asked for the format
  // The device's side: a sample every 10 ms of its clock, sent with up to 4 ms of jitter.
  std::thread player([&] {
    device.send("~AMGQUA");
    for (int k = 0; k < 20; ++k) {
      if (k == 5) device.send("$AMGQUA,1166,-3,2,9x1,628,8,-400,9,-18,0,0,0,8192,14189");  // a corrupt digit
      if (k == 9) device.send("$AMGQUA,1299,-3,2,981");                                    // cut short
      if (k == 13) device.send("\x01\x7f garbage");
      std::this_thread::sleep_for(std::chrono::microseconds(8000 + (k * 1237) % 4000));
      device.send("$AMGQUA," + std::to_string(1000 + 10 * k) + ",-3,2,981,628,8,-400,9,-18,0,0,0,8192,14189");
    }
  });
  const auto samples = read_for(stream, 400ms);
  player.join();
  ASSERT_EQ(samples.size(), 20u);
  EXPECT_EQ(stream.counters().bad_lines, 3u);
  EXPECT_EQ(stream.counters().replies, 1u);
  EXPECT_NEAR(samples[0].linear_acceleration.z(), 9.81, 1e-12);
  ASSERT_TRUE(samples[0].orientation && samples[0].magnetic_field);
  EXPECT_EQ(samples[0].frame, "ocams_imu");
  for (std::size_t i = 1; i < samples.size(); ++i) {
    EXPECT_GE(samples[i].stamp, samples[i - 1].stamp);
    // 10 ms apart on the device clock: the stamps keep that spacing, not the arrival's
    EXPECT_NEAR(static_cast<double>((samples[i].stamp - samples[i - 1].stamp).count()), 10e6, 6e6);
  }
}

TEST(OcamsImuPort, AHangUpIsCountedAndTheDeviceIsReopenedWhenItReturns) {
  const auto link = link_path();
  auto device = std::make_unique<FakeImuPort>(link);
  ImuStreamOptions o;
  o.port = link.string();
  ImuStream stream(o, steady_now);
  device->received(500ms);
  device->send("$AMGQUA,10,-3,2,981,628,8,-400,9,-18,0,0,0,8192,14189");
  EXPECT_EQ(read_for(stream, 100ms).size(), 1u);
  device->hang_up();
  read_for(stream, 100ms);
  EXPECT_EQ(stream.counters().hangups, 1u);
  EXPECT_FALSE(stream.connected());
  device = std::make_unique<FakeImuPort>(link);  // plugged back: a new tty behind the same name
  const auto back = std::chrono::steady_clock::now();
  while (!stream.connected() && std::chrono::steady_clock::now() - back < 1s) stream.read(20ms);
  ASSERT_TRUE(stream.connected());
  EXPECT_LT(std::chrono::steady_clock::now() - back, 1s);
  EXPECT_EQ(stream.counters().reconnects, 1u);
  EXPECT_EQ(device->received(500ms), "@AMGQUA\r\n");
  device->send("$AMGQUA,20,-3,2,981,628,8,-400,9,-18,0,0,0,8192,14189");
  EXPECT_EQ(read_for(stream, 100ms).size(), 1u);
}

TEST(OcamsImuPort, NoPortSaysSo) {
  ImuStreamOptions o;
  o.port = "/nonexistent/ttyACM9";
  try {
    ImuStream stream(o, steady_now);
    FAIL() << "opened a missing port";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("no oCamS IMU at /nonexistent/ttyACM9"));
  }
}
