// The V4L2 capture against a fake device: the format and rate are set and checked against what
// the device offers, frames come back whole, and short, flagged, late and lost frames, controls
// out of range and a device that vanishes are each handled as they should be.
#include <gmock/gmock.h>

#include "kestrel/testing/fake_v4l2.hpp"
#include "kestrel/v4l2/v4l2_camera.hpp"

using namespace kestrel;
using namespace kestrel::v4l2;
using kestrel::testing::FakeV4l2;

namespace {

std::vector<std::uint8_t> bytes(std::size_t n, std::uint8_t v) { return std::vector<std::uint8_t>(n, v); }
constexpr std::size_t kVga = 640 * 480 * 2;

}  // namespace

TEST(V4l2Camera, StreamsTheFormatAskedForAndHandsFramesBackWhole) {
  FakeV4l2 dev;
  V4l2Camera cam(dev, dev.path);
  const DeviceInfo info = cam.describe();
  EXPECT_EQ(info.card, "oCamS-1CGN-U");
  ASSERT_EQ(info.modes.size(), 2u);
  EXPECT_EQ(fourcc_text(info.modes[0].fourcc), "YUYV");
  EXPECT_THAT(info.modes[1].fps, ::testing::Contains(30.0));
  cam.start({640, 480, 30});
  EXPECT_TRUE(dev.streaming());
  dev.frames.push_back({bytes(kVga, 1)});
  dev.frames.push_back({bytes(kVga, 2)});
  auto f = cam.next(std::chrono::milliseconds(100));
  ASSERT_TRUE(f);
  EXPECT_EQ(f->data.size(), kVga);
  EXPECT_EQ(f->data[kVga - 1], 1);
  f = cam.next(std::chrono::milliseconds(100));
  ASSERT_TRUE(f);
  EXPECT_EQ(f->data[0], 2);
  EXPECT_FALSE(cam.next(std::chrono::milliseconds(20)));  // nothing more: a timeout, not an error
  EXPECT_EQ(cam.counters().frames, 2u);
  cam.stop();
  EXPECT_FALSE(dev.streaming());
}

TEST(V4l2Camera, AFormatOrRateTheDeviceDoesNotOfferIsRefusedWithWhatItOffers) {
  FakeV4l2 dev;
  V4l2Camera cam(dev, dev.path);
  try {
    cam.start({800, 600, 30});
    FAIL() << "800x600 accepted";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("does not stream YUYV 800x600: it offers"));
    EXPECT_THAT(e.what(), ::testing::HasSubstr("YUYV 640x480 @ 45 30 25 20 15 10"));
  }
  EXPECT_THROW(cam.start({640, 480, 60}), Error);
}

TEST(V4l2Camera, ShortFlaggedAndLostFramesAreCountedAndSkipped) {
  FakeV4l2 dev;
  V4l2Camera cam(dev, dev.path);
  cam.start({640, 480, 30});
  dev.frames.push_back({bytes(kVga / 2, 9), {}, false, kVga / 2});  // cut short on the bus
  dev.frames.push_back({bytes(kVga, 8), {}, true});                 // the driver saw it corrupt
  dev.frames.push_back({bytes(kVga, 3), {}, false, {}, 3});         // two lost before it
  auto f = cam.next(std::chrono::milliseconds(100));
  ASSERT_TRUE(f);
  EXPECT_EQ(f->data[0], 3);
  EXPECT_EQ(cam.counters().short_frames, 1u);
  EXPECT_EQ(cam.counters().error_frames, 1u);
  EXPECT_EQ(cam.counters().sequence_gaps, 2u);
}

TEST(V4l2Camera, ALateFrameIsWaitedForUpToTheTimeout) {
  FakeV4l2 dev;
  V4l2Camera cam(dev, dev.path);
  cam.start({640, 480, 30});
  dev.frames.push_back({bytes(kVga, 4), std::chrono::milliseconds(80)});
  EXPECT_FALSE(cam.next(std::chrono::milliseconds(30)));
  auto f = cam.next(std::chrono::milliseconds(200));
  ASSERT_TRUE(f);
  EXPECT_EQ(f->data[0], 4);
}

TEST(V4l2Camera, AMissingOrVanishingDeviceIsDeviceLost) {
  FakeV4l2 dev;
  dev.present = false;
  EXPECT_THROW(V4l2Camera(dev, dev.path), DeviceLost);
  dev.present = true;
  V4l2Camera cam(dev, dev.path);
  cam.start({640, 480, 30});
  dev.frames.push_back({bytes(kVga, 5)});
  dev.unplug_when_empty = true;
  EXPECT_TRUE(cam.next(std::chrono::milliseconds(100)));
  EXPECT_THROW(cam.next(std::chrono::milliseconds(100)), DeviceLost);
}

TEST(V4l2Camera, ControlsAreSetWithinTheirRange) {
  FakeV4l2 dev;
  V4l2Camera cam(dev, dev.path);
  cam.set_control(V4L2_CID_GAIN, 80);
  EXPECT_EQ(cam.control(V4L2_CID_GAIN), 80);
  try {
    cam.set_control(V4L2_CID_EXPOSURE_ABSOLUTE, 900);
    FAIL() << "an exposure out of range was set";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("Exposure Time, Absolute 900 is outside [1, 625]"));
  }
  EXPECT_FALSE(cam.control_range(V4L2_CID_HUE));
  EXPECT_THROW(cam.set_control(V4L2_CID_HUE, 1), Error);
}
