// dds_bridge's two halves on the loopback interface: what one publishes, the other rebuilds as the
// same kestrel messages (the recording's ROS 2 mapping, both ways), under the topic names and types
// ROS 2 gives them; bytes that do not decode are counted and dropped.
#include <gmock/gmock.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <kestrel/dds/discovery.hpp>
#include <kestrel/dds/ros2_names.hpp>
#include <kestrel/error.hpp>
#include <kestrel/messages/detections.hpp>
#include <kestrel/messages/point_cloud.hpp>
#include <kestrel/messages/tracks.hpp>
#include <kestrel/messages/vehicle_state.hpp>
#include <kestrel/testing/dds_loopback.hpp>
#include <thread>

#include "dds_publication.hpp"
#include "dds_subscription.hpp"

namespace kestrel::dds_bridge {
namespace {

using namespace std::chrono_literals;

class DdsBridge : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { domain_ = testing::use_dds_loopback(); }
  static std::uint32_t domain_;

  template <class T>
  static Envelope envelope(const T& message, std::string_view node, std::string_view port) {
    Envelope e;
    e.payload = std::make_shared<const T>(message);
    e.type = MessageTraits<T>::name;
    e.source_node = node;
    e.source_port = port;
    return e;
  }

  // Takes until `count` messages came or 10 s passed.
  static std::vector<std::pair<std::size_t, std::shared_ptr<const void>>> receive(DdsSubscription& s,
                                                                                  std::size_t count) {
    std::vector<std::pair<std::size_t, std::shared_ptr<const void>>> got;
    Logger log("ground");
    const auto deadline = std::chrono::steady_clock::now() + 10s;
    while (got.size() < count && std::chrono::steady_clock::now() < deadline) {
      s.take(log, [&](std::size_t port, std::shared_ptr<const void> m, const dds::WriterMetadata&) {
        got.emplace_back(port, std::move(m));
      });
      std::this_thread::sleep_for(5ms);
    }
    return got;
  }
};
std::uint32_t DdsBridge::domain_ = 0;

msg::Tracks known_tracks() {
  msg::Tracks t;
  t.stamp = Time(66'000'000);
  msg::Track a;
  a.id = 7;
  a.age = 12;
  a.hits = 11;
  a.misses = 1;
  a.state = Eigen::VectorXd::LinSpaced(9, 1.0, 9.0);
  a.covariance = Eigen::MatrixXd::Identity(9, 9) * 0.25;
  a.detection = {0.5, -0.25, 6.0};
  t.items = {a};
  t.selected_id = 7;
  return t;
}

TEST_F(DdsBridge, WhatOneSidePublishesTheOtherRebuilds) {
  dds::Participant vehicle(domain_), ground(domain_);
  DdsSubscription subscription(ground, dds::QosTable{},
                               {{"tracks", "kestrel.Tracks", "/vehicle/tracker/tracks"},
                                {"detections", "kestrel.Detections", "/vehicle/detector/detections"},
                                {"state", "kestrel.VehicleState", "/vehicle/sim/state"}});
  DdsPublication publication(vehicle, dds::QosTable{}, "/vehicle", true);

  msg::Detections d;
  d.stamp = Time(33'000'000);
  d.items.push_back({{0.1, -0.2, 5.0}, {0.4, 0.3, 0.2}, 57, 0.9});
  msg::VehicleState s;
  s.stamp = Time(5'000'000);
  s.position = {1, 2, 3};
  s.velocity = {2.0, 0.5, -0.25};
  s.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(0.2, 0.3, 1.0).normalized()));
  const msg::Tracks t = known_tracks();

  // Reliable and volatile: publish once both ends have matched.
  dds::Discovery discovery(vehicle);
  discovery.wait(10s, [](const auto& endpoints) { return endpoints.size() >= 3; });
  publication.publish(envelope(d, "detector", "detections"));  // creates the writers
  publication.publish(envelope(s, "sim", "state"));
  publication.publish(envelope(t, "tracker", "tracks"));
  auto got = receive(subscription, 3);
  if (got.size() < 3) {  // the first samples may have gone before the readers matched: again
    std::this_thread::sleep_for(500ms);
    publication.publish(envelope(d, "detector", "detections"));
    publication.publish(envelope(s, "sim", "state"));
    publication.publish(envelope(t, "tracker", "tracks"));
    auto more = receive(subscription, 3);
    got.insert(got.end(), more.begin(), more.end());
  }
  bool saw_tracks = false, saw_detections = false, saw_state = false;
  for (const auto& [port, m] : got) {
    if (port == 0) {
      const auto& back = *std::static_pointer_cast<const msg::Tracks>(m);
      ASSERT_EQ(back.items.size(), 1u);
      EXPECT_EQ(back.stamp, t.stamp);
      EXPECT_EQ(back.items[0].id, 7u);
      EXPECT_EQ(back.items[0].state, t.items[0].state);
      EXPECT_EQ(back.items[0].covariance, t.items[0].covariance);
      EXPECT_EQ(back.items[0].detection, t.items[0].detection);
      EXPECT_EQ(back.selected_id, std::optional<std::uint64_t>(7));
      saw_tracks = true;
    } else if (port == 1) {
      const auto& back = *std::static_pointer_cast<const msg::Detections>(m);
      ASSERT_EQ(back.items.size(), 1u);
      EXPECT_EQ(back.stamp, d.stamp);
      EXPECT_EQ(back.items[0].position, d.items[0].position);
      EXPECT_EQ(back.items[0].point_count, 57);
      saw_detections = true;
    } else {
      const auto& back = *std::static_pointer_cast<const msg::VehicleState>(m);
      EXPECT_EQ(back.position, s.position);
      EXPECT_EQ(back.orientation.coeffs(), s.orientation.coeffs());
      EXPECT_LT((back.velocity - s.velocity).norm(), 1e-14);
      saw_state = true;
    }
  }
  EXPECT_TRUE(saw_tracks && saw_detections && saw_state);
  EXPECT_EQ(subscription.bad_samples(), 0u);
  EXPECT_TRUE(subscription.never_matched().empty());
}

TEST_F(DdsBridge, TopicsAndTypesAreRosTwosWithViewerChannelsOnRequest) {
  dds::Participant vehicle(domain_), observer(domain_);
  DdsPublication with_viewers(vehicle, dds::QosTable{}, "", true);
  with_viewers.publish(envelope(known_tracks(), "tracker", "tracks"));
  dds::Participant other(domain_);
  DdsPublication without(other, dds::QosTable{}, "/plain", false);
  without.publish(envelope(known_tracks(), "tracker", "tracks"));

  dds::Discovery discovery(observer);
  const auto found = discovery.wait(10s, [](const auto& endpoints) { return endpoints.size() >= 3; });
  std::map<std::string, std::string> types;
  for (const auto& e : found) types[e.dds_topic] = e.dds_type;
  EXPECT_EQ(types["rt/tracker/tracks"], "kestrel_msgs::msg::dds_::Tracks_");
  EXPECT_EQ(types["rt/tracker/tracks/markers"], "visualization_msgs::msg::dds_::MarkerArray_");
  EXPECT_EQ(types["rt/plain/tracker/tracks"], "kestrel_msgs::msg::dds_::Tracks_");
  EXPECT_EQ(types.count("rt/plain/tracker/tracks/markers"), 0u);
  EXPECT_EQ(types.size(), 3u);
}

TEST_F(DdsBridge, ACloudsScaleTravelsInItsWritersMetadata) {
  dds::Participant vehicle(domain_), ground(domain_);
  DdsSubscription subscription(ground, dds::QosTable{}, {{"cloud", "kestrel.PointCloud", "/depth/cloud"}});
  DdsPublication publication(vehicle, dds::QosTable{}, "", true);
  msg::PointCloud c;
  c.stamp = Time(42);
  auto points = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  points->push_back({1.5f, -2.25f, 7.0f});
  c.points = points;
  c.pixels_per_point = 4;
  c.focal_baseline_px_m = 36.48;
  std::vector<std::pair<std::size_t, std::shared_ptr<const void>>> got;
  for (int attempt = 0; attempt < 20 && got.empty(); ++attempt) {
    publication.publish(envelope(c, "depth", "cloud"));
    got = receive(subscription, 1);
  }
  ASSERT_FALSE(got.empty());
  const auto& back = *std::static_pointer_cast<const msg::PointCloud>(got[0].second);
  EXPECT_EQ(back.pixels_per_point, 4);
  EXPECT_EQ(back.focal_baseline_px_m, 36.48);
  ASSERT_EQ(back.points->size(), 1u);
  EXPECT_EQ(back.points->points[0].y, -2.25f);
}

TEST_F(DdsBridge, BytesThatDoNotDecodeAreCountedAndDropped) {
  dds::Participant rogue(domain_), ground(domain_);
  DdsSubscription subscription(ground, dds::QosTable{}, {{"tracks", "kestrel.Tracks", "/tracker/tracks"}});
  dds::Writer writer(rogue, "rt/tracker/tracks", "kestrel_msgs::msg::dds_::Tracks_", dds::Qos{});
  ASSERT_TRUE(writer.wait_for_readers(1, 10s));
  const std::vector<std::uint8_t> garbage = {0x00, 0x01, 0x00, 0x00, 0xff, 0xff, 0xff, 0x7f, 1, 2, 3};
  writer.write(garbage);
  Logger log("ground");
  const auto deadline = std::chrono::steady_clock::now() + 10s;
  std::size_t published = 0;
  while (subscription.bad_samples() == 0 && std::chrono::steady_clock::now() < deadline) {
    subscription.take(log, [&](std::size_t, std::shared_ptr<const void>, const dds::WriterMetadata&) { ++published; });
    std::this_thread::sleep_for(5ms);
  }
  EXPECT_EQ(subscription.bad_samples(), 1u);
  EXPECT_EQ(published, 0u);
}

TEST_F(DdsBridge, AnOutputWhoseNameRosTwoRefusesIsAClearError) {
  dds::Participant vehicle(domain_);
  DdsPublication publication(vehicle, dds::QosTable{}, "", true);
  try {
    publication.publish(envelope(known_tracks(), "my-tracker", "tracks"));
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("'/my-tracker/tracks'"));
  }
}

}  // namespace
}  // namespace kestrel::dds_bridge
