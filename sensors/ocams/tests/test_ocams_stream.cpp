// The oCamS stream against a fake device: its clock mapped onto the runtime's, its controls set,
// and a stall, an unplugging and a return lived through as the node needs.
#include <gmock/gmock.h>
#include <linux/videodev2.h>

#include <random>

#include "kestrel/testing/fake_v4l2.hpp"
#include "kestrel/testing/steady_now.hpp"
#include "ocams_stream.hpp"
#include "raw_frame.hpp"

using namespace kestrel;
using namespace kestrel::ocams;
using kestrel::testing::FakeV4l2;
using namespace std::chrono_literals;
using kestrel::testing::steady_now;

namespace {

std::vector<std::uint8_t> frame(std::uint32_t device_ms) {
  return pack(cv::Mat(480, 640, CV_8UC1, cv::Scalar(10)), cv::Mat(480, 640, CV_8UC1, cv::Scalar(20)), device_ms);
}

StreamOptions options(const FakeV4l2& dev) {
  StreamOptions o;
  o.device = dev.path;
  o.format = {640, 480, 30};
  o.stall_timeout = 150ms;
  return o;
}

}  // namespace

TEST(DeviceClock, StampsAreTheDeviceTimePlusTheSmallestDelaySeen) {
  DeviceClock clock;
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> jitter_us(0, 12000);
  const std::int64_t offset_ns = 7'000'000'000;  // the device started 7 s before the run clock
  Time stamp{0};
  for (std::uint32_t k = 0; k < 200; ++k) {
    const std::uint32_t device_ms = 1000 + 33 * k;
    const Time arrival(std::int64_t{device_ms} * 1'000'000 - offset_ns + 4'000'000 + jitter_us(rng) * 1000);
    stamp = clock.map(device_ms, arrival);
    EXPECT_LE(stamp, arrival);
  }
  // After many frames: capture time = device time - offset + the 4 ms transport floor, to the jitter's low tail.
  const std::int64_t truth = (std::int64_t{1000 + 33 * 199} * 1'000'000 - offset_ns) + 4'000'000;
  EXPECT_NEAR(static_cast<double>(stamp.count()), static_cast<double>(truth), 300'000.0);
}

TEST(DeviceClock, TheCounterWrapsAndARestartStartsAfresh) {
  DeviceClock clock;
  const std::uint32_t before_wrap = 0xFFFFFFF0u;
  const Time a = clock.map(before_wrap, Time(1'000'000'000));
  const Time b = clock.map(before_wrap + 33u, Time(1'033'000'000));  // wrapped to 17
  EXPECT_EQ(b - a, Time(33'000'000));
  EXPECT_EQ(clock.restarts(), 0u);
  const Time c = clock.map(5, Time(1'100'000'000));  // back to 5 ms: the device restarted
  EXPECT_EQ(clock.restarts(), 1u);
  EXPECT_GE(c, b);
}

TEST(OcamsStream, NoDeviceSaysNoOcamsFound) {
  FakeV4l2 dev;
  dev.present = false;
  try {
    OcamsStream stream(dev, options(dev), steady_now);
    FAIL() << "opened a missing camera";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("no oCamS found at /dev/video-fake"));
  }
}

TEST(OcamsStream, SetsItsControlsAndStampsFramesOnTheRuntimeClock) {
  FakeV4l2 dev;
  StreamOptions o = options(dev);
  o.controls.gain = 80;
  o.controls.auto_exposure = false;
  o.controls.exposure = 150;
  OcamsStream stream(dev, o, steady_now);
  EXPECT_EQ(stream.applied_controls().at("gain"), 80);
  EXPECT_EQ(stream.applied_controls().at("exposure"), 150);
  EXPECT_EQ(stream.applied_controls().at("auto_exposure"), V4L2_EXPOSURE_MANUAL);
  EXPECT_EQ(stream.applied_controls().at("white_balance_red"), 150);  // the device's own
  dev.frames.push_back({frame(5000)});
  const Time before = steady_now();
  const auto f = stream.next(100ms);
  ASSERT_TRUE(f);
  EXPECT_EQ(f->device_ms, 5000u);
  EXPECT_LE(f->stamp, steady_now());
  EXPECT_GE(f->stamp, before - Time(1'000'000));
  o.controls.exposure = 5000;
  EXPECT_THROW(OcamsStream(dev, o, steady_now), Error);
}

TEST(OcamsStream, AStallIsAnErrorWithoutReconnect) {
  FakeV4l2 dev;
  StreamOptions o = options(dev);
  o.reconnect = false;
  OcamsStream stream(dev, o, steady_now);
  EXPECT_FALSE(stream.next(100ms));
  try {
    stream.next(100ms);
    FAIL() << "a stalled stream went on";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("no frame for 150 ms: the stream stalled"));
  }
}

TEST(OcamsStream, AnUnpluggedCameraIsReopenedWhenItComesBack) {
  FakeV4l2 dev;
  OcamsStream stream(dev, options(dev), steady_now);
  dev.frames.push_back({frame(100)});
  dev.unplug_when_empty = true;
  ASSERT_TRUE(stream.next(100ms));
  EXPECT_FALSE(stream.next(100ms));  // gone
  EXPECT_FALSE(stream.connected());
  EXPECT_FALSE(stream.next(50ms));  // still away
  dev.present = true;
  dev.unplug_when_empty = false;
  dev.frames.push_back({frame(200)});
  const auto back = std::chrono::steady_clock::now();
  std::optional<RawCapture> f;
  while (!f && std::chrono::steady_clock::now() - back < 1s) f = stream.next(50ms);
  ASSERT_TRUE(f);
  EXPECT_LT(std::chrono::steady_clock::now() - back, 1s);
  EXPECT_EQ(f->device_ms, 200u);
  EXPECT_EQ(stream.counters().disconnects, 1u);
  EXPECT_EQ(stream.counters().reconnects, 1u);
  EXPECT_EQ(dev.opens, 2);
}
