// ROS 2's names on the wire, the QoS words and the writer metadata: pure functions, known answers.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <kestrel/dds/cdr_padding.hpp>
#include <kestrel/dds/qos.hpp>
#include <kestrel/dds/ros2_names.hpp>
#include <kestrel/dds/writer.hpp>
#include <kestrel/error.hpp>

namespace kestrel::dds {
namespace {

using ::testing::HasSubstr;

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(DdsNames, TopicsGetRosTwosPrefix) {
  EXPECT_EQ(ros2_dds_topic("/camera/frame/left"), "rt/camera/frame/left");
  EXPECT_EQ(ros2_dds_topic("/tf"), "rt/tf");
  EXPECT_EQ(ros2_topic_of("rt/camera/frame/left"), "/camera/frame/left");
  EXPECT_EQ(ros2_topic_of("DCPSParticipant"), std::nullopt);
  EXPECT_EQ(ros2_topic_of("rq/add_twoRequest").has_value(), false);  // a service, not a topic
}

TEST(DdsNames, TopicsRosTwoRefusesAreRefusedWithTheReason) {
  EXPECT_THAT(error_of([] { ros2_dds_topic("camera"); }), HasSubstr("must start with '/'"));
  EXPECT_THAT(error_of([] { ros2_dds_topic("/camera/"); }), HasSubstr("must not end with '/'"));
  EXPECT_THAT(error_of([] { ros2_dds_topic("/a//b"); }), HasSubstr("empty token"));
  EXPECT_THAT(error_of([] { ros2_dds_topic("/a/2d"); }), HasSubstr("must not start with a digit ('2d')"));
  EXPECT_THAT(error_of([] { ros2_dds_topic("/sim-stereo/frame"); }), HasSubstr("'-' is not allowed"));
}

TEST(DdsNames, TypesAreManglednAsRosTwoDoes) {
  EXPECT_EQ(ros2_dds_type("sensor_msgs/msg/Image"), "sensor_msgs::msg::dds_::Image_");
  EXPECT_EQ(ros2_dds_type("kestrel_msgs/msg/Detections"), "kestrel_msgs::msg::dds_::Detections_");
  EXPECT_EQ(ros2_type_of("nav_msgs::msg::dds_::Odometry_"), "nav_msgs/msg/Odometry");
  EXPECT_EQ(ros2_type_of("HelloWorld"), std::nullopt);
  EXPECT_THAT(error_of([] { ros2_dds_type("sensor_msgs/Image"); }), HasSubstr("pkg/msg/Type"));
}

TEST(DdsQos, DefaultsAreRosTwos) { EXPECT_EQ(to_string(Qos{}), "reliable, keep last 10, volatile"); }

TEST(DdsQos, WordsChangeTheBase) {
  const Qos q = parse_qos("best_effort, depth=1 transient_local", Qos{});
  EXPECT_EQ(q.reliability, Reliability::best_effort);
  EXPECT_EQ(q.depth, 1);
  EXPECT_EQ(q.durability, Durability::transient_local);
  EXPECT_THAT(error_of([] { parse_qos("reliable fast", Qos{}); }), HasSubstr("'fast' is not one of"));
  EXPECT_THAT(error_of([] { parse_qos("depth=0", Qos{}); }), HasSubstr("from 1 to 100000"));
  EXPECT_THAT(error_of([] { parse_qos("depth=ten", Qos{}); }), HasSubstr("whole number"));
}

TEST(DdsQos, OverridesApplyPerTopicInOrder) {
  const QosTable table(Qos{},
                       "/camera/*: best_effort depth=1\n/camera/frame/left/camera_info: transient_local; /x: depth=3");
  EXPECT_EQ(table.for_topic("/tracker/tracks"), Qos{});
  EXPECT_EQ(table.for_topic("/camera/frame/left"), (Qos{Reliability::best_effort, 1, Durability::volatile_}));
  EXPECT_EQ(table.for_topic("/camera/frame/left/camera_info"),
            (Qos{Reliability::best_effort, 1, Durability::transient_local}));
  EXPECT_THAT(error_of([] { QosTable(Qos{}, "/camera best_effort"); }), HasSubstr("TOPIC_PATTERN: WORDS"));
  EXPECT_THAT(error_of([] { QosTable(Qos{}, "/camera: quick"); }), HasSubstr("'quick'"));
}

TEST(DdsMetadata, RoundTripsAndRefusesSeparators) {
  const WriterMetadata m{{"pixels_per_point", "4"}, {"focal_baseline_px_m", "48.5"}};
  EXPECT_EQ(encode_metadata(m), "focal_baseline_px_m=48.5;pixels_per_point=4;");
  EXPECT_EQ(decode_metadata(encode_metadata(m)), m);
  EXPECT_EQ(decode_metadata("enclave=/;junk;a=b"), (WriterMetadata{{"enclave", "/"}, {"a", "b"}}));
  EXPECT_THAT(error_of([] { encode_metadata({{"a;b", "1"}}); }), HasSubstr("must not hold ';'"));
}

TEST(DdsPadding, WholeWordsOnTheWireTheMessageBack) {
  const std::vector<std::uint8_t> odd = {0x00, 0x01, 0x00, 0x00, 7, 8, 9, 10, 11};
  const auto padded = pad_cdr(odd);
  EXPECT_EQ(padded, (std::vector<std::uint8_t>{0x00, 0x01, 0x00, 0x03, 7, 8, 9, 10, 11, 0, 0, 0}));
  auto back = padded;
  strip_cdr_padding(back);
  EXPECT_EQ(back, odd);
  const std::vector<std::uint8_t> whole = {0x00, 0x01, 0x00, 0x00, 1, 2, 3, 4};
  EXPECT_EQ(pad_cdr(whole), whole);
  // Options that count more padding than the sample holds are left alone.
  std::vector<std::uint8_t> short_sample = {0x00, 0x01, 0x00, 0x03, 1};
  strip_cdr_padding(short_sample);
  EXPECT_EQ(short_sample.size(), 5u);
}

}  // namespace
}  // namespace kestrel::dds
