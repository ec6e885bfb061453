// Writers, readers and discovery through Cyclone, between two participants of this process on the
// loopback interface: bytes arrive as written, QoS is applied, metadata and types are discovered.
#include <gtest/gtest.h>

#include <kestrel/dds/discovery.hpp>
#include <kestrel/dds/reader.hpp>
#include <kestrel/dds/writer.hpp>
#include <kestrel/error.hpp>
#include <kestrel/testing/dds_loopback.hpp>
#include <thread>

namespace kestrel::dds {
namespace {

using namespace std::chrono_literals;

class DdsLoopback : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { domain_ = testing::use_dds_loopback(); }
  static std::uint32_t domain_;
};
std::uint32_t DdsLoopback::domain_ = 0;

// A CDR message as ROS 2 writes it: little-endian encapsulation header, then the fields.
std::vector<std::uint8_t> message(std::uint8_t fill, std::size_t size) {
  std::vector<std::uint8_t> bytes(size, fill);
  bytes[0] = 0x00;
  bytes[1] = 0x01;
  bytes[2] = bytes[3] = 0x00;
  return bytes;
}

std::vector<ReceivedSample> take_until(Reader& reader, std::size_t count, std::chrono::milliseconds timeout) {
  std::vector<ReceivedSample> got;
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (got.size() < count && std::chrono::steady_clock::now() < deadline) {
    reader.take([&](ReceivedSample&& s) { got.push_back(std::move(s)); });
    std::this_thread::sleep_for(5ms);
  }
  return got;
}

TEST_F(DdsLoopback, BytesArriveAsWrittenInOrder) {
  Participant vehicle(domain_), ground(domain_);
  Writer writer(vehicle, "rt/test/bytes", "kestrel_msgs::msg::dds_::Detections_", Qos{});
  Reader reader(ground, "rt/test/bytes", "kestrel_msgs::msg::dds_::Detections_", Qos{});
  ASSERT_TRUE(writer.wait_for_readers(1, 10s));
  ASSERT_TRUE(reader.wait_for_writers(1, 10s));
  // One small, one larger than a UDP datagram (Cyclone fragments it), and one that is no whole
  // number of 4-byte words (padded on the wire, the padding taken off again).
  const auto small = message(7, 24), large = message(9, 200000), odd = message(3, 27);
  writer.write(small);
  writer.write(large);
  writer.write(odd);
  const auto got = take_until(reader, 3, 10s);
  ASSERT_EQ(got.size(), 3u);
  EXPECT_EQ(got[0].cdr, small);
  EXPECT_EQ(got[1].cdr, large);
  EXPECT_EQ(got[2].cdr, odd);
  EXPECT_GT(got[0].source_time_ns, 0);
  EXPECT_EQ(reader.lost_samples(), 0u);
}

TEST_F(DdsLoopback, AnotherTypeNameOnTheTopicDoesNotMatch) {
  Participant vehicle(domain_), ground(domain_);
  Writer writer(vehicle, "rt/test/typed", "nav_msgs::msg::dds_::Odometry_", Qos{});
  Reader reader(ground, "rt/test/typed", "sensor_msgs::msg::dds_::Image_", Qos{});
  EXPECT_FALSE(reader.wait_for_writers(1, 1500ms));
}

TEST_F(DdsLoopback, ABestEffortWriterDoesNotServeAReliableReader) {
  Participant vehicle(domain_), ground(domain_);
  Writer writer(vehicle, "rt/test/qos", "std_msgs::msg::dds_::String_",
                Qos{Reliability::best_effort, 10, Durability::volatile_});
  Reader reliable(ground, "rt/test/qos", "std_msgs::msg::dds_::String_", Qos{});
  Reader best_effort(ground, "rt/test/qos", "std_msgs::msg::dds_::String_",
                     Qos{Reliability::best_effort, 10, Durability::volatile_});
  ASSERT_TRUE(best_effort.wait_for_writers(1, 10s));
  EXPECT_EQ(reliable.matched_writers(), 0u);  // DDS's requested-offered rule, as ROS 2 has it
}

TEST_F(DdsLoopback, TransientLocalKeepsTheLastSamplesForALateReader) {
  Participant vehicle(domain_), ground(domain_);
  const Qos latched{Reliability::reliable, 2, Durability::transient_local};
  Writer writer(vehicle, "rt/test/latched", "sensor_msgs::msg::dds_::CameraInfo_", latched);
  for (std::uint8_t i = 1; i <= 3; ++i) writer.write(message(i, 16));
  Reader late(ground, "rt/test/latched", "sensor_msgs::msg::dds_::CameraInfo_", latched);
  const auto got = take_until(late, 2, 10s);
  ASSERT_EQ(got.size(), 2u);  // keep last 2: the first is gone
  EXPECT_EQ(got[0].cdr, message(2, 16));
  EXPECT_EQ(got[1].cdr, message(3, 16));
}

TEST_F(DdsLoopback, DiscoverySeesOthersEndpointsWithTypeQosAndMetadata) {
  Participant vehicle(domain_), ground(domain_);
  Writer writer(vehicle, "rt/test/cloud", "sensor_msgs::msg::dds_::PointCloud2_",
                Qos{Reliability::best_effort, 1, Durability::volatile_}, {{"pixels_per_point", "4"}});
  Reader reader(ground, "rt/test/cloud", "sensor_msgs::msg::dds_::PointCloud2_",
                Qos{Reliability::best_effort, 1, Durability::volatile_});
  Discovery discovery(ground);
  const auto found = discovery.wait(10s, [](const auto& endpoints) {
    return std::any_of(endpoints.begin(), endpoints.end(),
                       [](const auto& e) { return e.dds_topic == "rt/test/cloud"; });
  });
  std::vector<DiscoveredEndpoint> cloud;
  for (const auto& e : found)
    if (e.dds_topic == "rt/test/cloud") cloud.push_back(e);
  ASSERT_EQ(cloud.size(), 1u);  // the writer; the reader is ground's own
  EXPECT_TRUE(cloud[0].writer);
  EXPECT_EQ(cloud[0].dds_type, "sensor_msgs::msg::dds_::PointCloud2_");
  EXPECT_EQ(cloud[0].qos, (Qos{Reliability::best_effort, 1, Durability::volatile_}));
  EXPECT_EQ(cloud[0].metadata.at("pixels_per_point"), "4");
  EXPECT_NE(cloud[0].participant, ground.guid());

  // New metadata reaches the readers through discovery.
  ASSERT_TRUE(reader.wait_for_writers(1, 10s));
  writer.set_metadata({{"pixels_per_point", "2"}});
  writer.write(message(1, 8));
  const auto got = take_until(reader, 1, 10s);
  ASSERT_EQ(got.size(), 1u);
  const auto deadline = std::chrono::steady_clock::now() + 10s;
  while (reader.writer_metadata(got[0].writer).count("pixels_per_point") == 0 ||
         reader.writer_metadata(got[0].writer).at("pixels_per_point") != "2") {
    ASSERT_LT(std::chrono::steady_clock::now(), deadline) << "the new metadata never arrived";
    std::this_thread::sleep_for(10ms);
  }
}

TEST_F(DdsLoopback, BadInputIsAClearError) {
  Participant p(domain_);
  Writer writer(p, "rt/test/bad", "std_msgs::msg::dds_::String_", Qos{});
  const std::vector<std::uint8_t> two(2, 0);
  EXPECT_THROW(writer.write(two), Error);
  EXPECT_THROW(Participant(233), Error);
}

}  // namespace
}  // namespace kestrel::dds
