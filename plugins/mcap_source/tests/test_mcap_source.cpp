// What mcap_source replays, on a recording whose content is known: messages come back per port in
// the log-time windows asked for, a stereo frame from its four channels, the rate from the log
// times, and a topic that is missing or of another type is refused with what the file holds.
#include <gmock/gmock.h>

#include <filesystem>
#include <kestrel/messages/ground_truth.hpp>
#include <kestrel/messages/stereo_frame.hpp>

#include "kestrel/mcap/writer.hpp"
#include "kestrel/ros2/cdr.hpp"
#include "kestrel/ros2/definitions.hpp"
#include "kestrel/ros2_messages/message_mapping.hpp"
#include "kestrel/testing/scratch_path.hpp"
#include "recorded_channels.hpp"

using namespace kestrel;
using namespace kestrel::replay;
namespace fs = std::filesystem;

namespace {

// Writes `message` as the recorder does, on the channels of `topic`, logged at `t`.
class TestRecording {
 public:
  explicit TestRecording(const fs::path& file) : writer_(file, mcap::WriterOptions{"ros2", "test", "", 0, 4096}) {}
  template <class T>
  void write(const T& message, const std::string& topic, std::uint64_t t) {
    const std::string type(MessageTraits<T>::name);
    const auto specs = ros2::channels_for(type, topic);
    const auto encoded = ros2::encode(type, &message, topic);
    for (const auto& m : encoded.messages) {
      const auto& spec = specs[m.channel];
      const std::string key = spec.topic;
      if (!channels_.count(key)) {
        const std::string& text = ros2::schema_text(spec.schema);
        const auto schema = writer_.add_schema(spec.schema, "ros2msg",
                                               {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()});
        channels_[key] = writer_.add_channel(
            schema, spec.topic, "cdr",
            spec.derived ? mcap::KeyValues{} : mcap::KeyValues(encoded.metadata.begin(), encoded.metadata.end()));
      }
      writer_.write_message(channels_[key], t, t, m.cdr, m.sequence);
    }
  }
  // One message of a ROS 2 type on a topic of any name, as another driver's bag holds it.
  void write_raw(const std::string& topic, const std::string& schema_name, const std::vector<std::uint8_t>& cdr,
                 std::uint64_t t) {
    if (!channels_.count(topic)) {
      const std::string& text = ros2::schema_text(schema_name);
      const auto schema =
          writer_.add_schema(schema_name, "ros2msg", {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()});
      channels_[topic] = writer_.add_channel(schema, topic, "cdr", {});
    }
    writer_.write_message(channels_[topic], t, t, cdr, 0);
  }
  void finish() { writer_.finish(); }

 private:
  mcap::Writer writer_;
  std::map<std::string, std::uint16_t> channels_;
};

msg::GroundTruth truth(std::uint64_t id, double x) {
  msg::GroundTruth g;
  g.stamp = Time(static_cast<std::int64_t>(id) * 40'000'000);
  g.objects.push_back({id, {x, 0, 0}, {0, 0, x}, {0, 0, 0}, true});
  return g;
}

msg::StereoFrame frame(std::uint64_t index, std::int64_t stamp_ns) {
  msg::StereoFrame f;
  f.stamp = Time(stamp_ns);
  f.frame_index = index;
  f.left = cv::Mat(2, 3, CV_8UC1, cv::Scalar(static_cast<double>(index)));
  f.right = cv::Mat(2, 3, CV_8UC1, cv::Scalar(static_cast<double>(index + 1)));
  f.calibration = {3, 2, 300.0, 300.0, 1.0, 1.0, 0.12};
  return f;
}

// sensor_msgs/msg/Image and CameraInfo as a ROS 2 stereo driver writes them: stamp 1.25 s,
// frame "stereo", a colour image in rgb8 whose pixel k is (k, 10 k, 20 k) + `offset`.
std::vector<std::uint8_t> driver_image(int offset) {
  ros2::CdrWriter w;
  w.i32(1);
  w.u32(250'000'000);
  w.string("stereo");
  w.u32(2);  // height
  w.u32(3);  // width
  w.string("rgb8");
  w.u8(0);
  w.u32(12);  // step: 9 bytes of pixels and 3 of padding
  std::vector<std::uint8_t> data(24, 0);
  for (int k = 0; k < 6; ++k)
    for (int c = 0; c < 3; ++c)
      data[static_cast<std::size_t>((k / 3) * 12 + (k % 3) * 3 + c)] =
          static_cast<std::uint8_t>(k * (c == 0 ? 1 : 10 * c) + offset);
  w.bytes(data);
  return w.take();
}
std::vector<std::uint8_t> driver_camera_info(double tx) {
  ros2::CdrWriter w;
  w.i32(1);
  w.u32(250'000'000);
  w.string("stereo");
  w.u32(2);
  w.u32(3);
  w.string("plumb_bob");
  w.sequence_length(5);
  for (int i = 0; i < 5; ++i) w.f64(i == 0 ? -0.1 : 0.0);  // of the raw images; P is the rectified camera
  for (double v : {310.0, 0.0, 1.0, 0.0, 310.0, 0.5, 0.0, 0.0, 1.0}) w.f64(v);
  for (double v : {1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0}) w.f64(v);
  for (double v : {300.0, 0.0, 1.5, tx, 0.0, 300.0, 0.75, 0.0, 0.0, 0.0, 1.0, 0.0}) w.f64(v);
  for (int i = 0; i < 6; ++i) w.u32(0);
  w.boolean(false);
  return w.take();
}

fs::path file(const std::string& name) {
  const auto dir = kestrel::testing::scratch_path("kestrel-mcap-source");
  fs::create_directories(dir);
  return dir / name;
}

}  // namespace

TEST(RecordedChannels, ReplaysEachPortInTheWindowsAskedForAtTheRecordedRate) {
  const auto f = file("truth.mcap");
  {
    TestRecording rec(f);
    for (std::uint64_t k = 0; k < 10; ++k) rec.write(truth(k, static_cast<double>(k)), "/cam/truth", k * 40'000'000);
    rec.write(frame(0, 0), "/cam/frame", 0);
    rec.write(frame(1, 40'000'000), "/cam/frame", 40'000'000);
    rec.finish();
  }
  RecordedChannels channels(
      f, {{"truth", "kestrel.GroundTruth", "/cam/truth"}, {"frame", "kestrel.StereoFrame", "/cam/frame"}});
  EXPECT_EQ(channels.busiest_rate_hz(), 25.0);  // 40 ms apart
  EXPECT_EQ(channels.end_time(), 360'000'000u);
  std::vector<std::pair<std::size_t, double>> got;
  auto collect = [&](std::size_t port, std::shared_ptr<const void> m) {
    if (port == 0) got.emplace_back(0, static_cast<const msg::GroundTruth*>(m.get())->objects[0].position_world.x());
    if (port == 1) got.emplace_back(1, static_cast<double>(static_cast<const msg::StereoFrame*>(m.get())->frame_index));
  };
  channels.replay(0, 40'000'001, collect);  // the first two of each
  EXPECT_THAT(got,
              ::testing::ElementsAre(std::pair<std::size_t, double>{0, 0.0}, std::pair<std::size_t, double>{1, 0.0},
                                     std::pair<std::size_t, double>{0, 1.0}, std::pair<std::size_t, double>{1, 1.0}));
  got.clear();
  channels.replay(40'000'001, 200'000'001, collect);
  EXPECT_EQ(got.size(), 4u);  // truths 2 to 5
  EXPECT_EQ(got.back().second, 5.0);
  EXPECT_EQ(channels.unpaired(), 0u);
}

TEST(RecordedChannels, AnotherDriversStereoTopicsArePairedIntoAFrame) {
  const auto f = file("driver.mcap");
  {
    TestRecording rec(f);
    rec.write_raw("/stereo/right/camera_info", "sensor_msgs/msg/CameraInfo", driver_camera_info(-300.0 * 0.12), 5);
    rec.write_raw("/stereo/left/image_rect_color", "sensor_msgs/msg/Image", driver_image(0), 6);
    rec.write_raw("/stereo/left/camera_info", "sensor_msgs/msg/CameraInfo", driver_camera_info(0.0), 7);
    rec.write_raw("/stereo/right/image_rect_color", "sensor_msgs/msg/Image", driver_image(1), 8);
    rec.finish();
  }
  RecordedChannels channels(f, {{"frame",
                                 "kestrel.StereoFrame",
                                 "/stereo/left/image_rect_color",
                                 {"/stereo/left/image_rect_color", "/stereo/right/image_rect_color",
                                  "/stereo/left/camera_info", "/stereo/right/camera_info"}}});
  std::shared_ptr<const msg::StereoFrame> got;
  channels.replay(0, 100, [&](std::size_t, std::shared_ptr<const void> m) {
    got = std::static_pointer_cast<const msg::StereoFrame>(m);
  });
  ASSERT_TRUE(got);
  EXPECT_EQ(got->stamp, Time(1'250'000'000));
  ASSERT_EQ(got->left.type(), CV_8UC3);
  ASSERT_EQ(got->left.size(), cv::Size(3, 2));
  EXPECT_EQ(got->left.at<cv::Vec3b>(1, 2), cv::Vec3b(100, 50, 5));  // pixel 5 (5, 50, 100) as BGR, padding skipped
  EXPECT_EQ(got->right.at<cv::Vec3b>(0, 0), cv::Vec3b(1, 1, 1));
  EXPECT_EQ(got->calibration.fx, 300.0);
  EXPECT_EQ(got->calibration.cy, 0.75);
  EXPECT_NEAR(got->calibration.baseline_m, 0.12, 1e-15);
  EXPECT_EQ(got->mount.parent_frame, "world");  // the bag says nothing of where the camera stood
  EXPECT_EQ(channels.unpaired(), 0u);

  EXPECT_THROW(RecordedChannels(f, {{"frame", "kestrel.StereoFrame", "/stereo", {"/stereo/left/image_rect_color"}}}),
               Error);
}

TEST(RecordedChannels, RefusesATopicThatIsMissingOrOfAnotherType) {
  const auto f = file("refuse.mcap");
  {
    TestRecording rec(f);
    rec.write(truth(0, 1.0), "/cam/truth", 0);
    rec.finish();
  }
  try {
    RecordedChannels channels(f, {{"frame", "kestrel.StereoFrame", "/cam/truth"}});
    FAIL() << "a missing frame topic was accepted";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("no channel /cam/truth/left of sensor_msgs/msg/Image"));
  }
  try {
    RecordedChannels channels(f, {{"detections", "kestrel.Detections", "/cam/truth"}});
    FAIL() << "a ground-truth topic was read as detections";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("it has kestrel_msgs/msg/GroundTruth (cdr)"));
  }
}

TEST(RecordedChannels, AFileCutShortReplaysEveryCompleteChunkAndEnds) {
  const auto whole = file("whole.mcap"), cut = file("cut.mcap");
  {
    TestRecording rec(whole);  // 4 KiB chunks: a few truths each
    for (std::uint64_t k = 0; k < 200; ++k) rec.write(truth(k, static_cast<double>(k)), "/cam/truth", k * 40'000'000);
    rec.finish();
  }
  const auto size = fs::file_size(whole);
  fs::copy_file(whole, cut, fs::copy_options::overwrite_existing);
  fs::resize_file(cut, size / 2);  // as a crash leaves it: no summary, a chunk cut in two
  RecordedChannels channels(cut, {{"truth", "kestrel.GroundTruth", "/cam/truth"}});
  EXPECT_THAT(channels.problems(), ::testing::Not(::testing::IsEmpty()));
  std::vector<double> got;
  auto collect = [&](std::size_t, std::shared_ptr<const void> m) {
    got.push_back(static_cast<const msg::GroundTruth*>(m.get())->objects[0].position_world.x());
  };
  for (std::uint64_t t = 0; t <= channels.end_time(); t += 40'000'000) channels.replay(t, t + 40'000'000, collect);
  ASSERT_GT(got.size(), 50u);  // about half of the 200, less the chunk that was cut
  EXPECT_LT(got.size(), 100u);
  for (std::size_t i = 0; i < got.size(); ++i) EXPECT_EQ(got[i], static_cast<double>(i));  // in order, none missing
  EXPECT_EQ(channels.end_time(), (got.size() - 1) * 40'000'000u);
}
