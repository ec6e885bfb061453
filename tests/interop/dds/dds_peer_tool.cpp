// kestrel's end of the DDS interop test (check_dds_idl.sh, check_dds_fastdds.sh), through
// dds_bridge's own publication and subscription:
//   dds_peer_tool publish DOMAIN SECONDS NODE SENT_JSON
//     publishes known messages as outputs of node NODE (/NODE/frame, /cloud, /state, /detections,
//     /tracks, /truth) at 10 Hz, and writes what each ROS 2 channel carried, as JSON lines, to
//     SENT_JSON for the script to compare with what the other side read;
//   dds_peer_tool expect DOMAIN TIMEOUT_S NODE
//     subscribes to /NODE/state, /detections, /tracks and /truth and checks that the messages are
//     those idl_publisher.c sends, field by field. Exit 0 once all four were right.
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <kestrel/dds/participant.hpp>
#include <kestrel/messages/detections.hpp>
#include <kestrel/messages/ground_truth.hpp>
#include <kestrel/messages/point_cloud.hpp>
#include <kestrel/messages/stereo_frame.hpp>
#include <kestrel/messages/tracks.hpp>
#include <kestrel/messages/vehicle_state.hpp>
#include <kestrel/ros2/cdr_json.hpp>
#include <kestrel/ros2/definitions.hpp>
#include <string>
#include <thread>

#include "dds_publication.hpp"
#include "dds_subscription.hpp"

using namespace kestrel;

namespace {

template <class T>
Envelope envelope(std::shared_ptr<const T> message, const std::string& node, const char* port) {
  static std::vector<std::string> names;  // the envelope views them for the whole run
  names.push_back(node);
  Envelope e;
  e.payload = std::move(message);
  e.type = MessageTraits<T>::name;
  e.source_node = names.back();
  e.source_port = port;
  return e;
}

std::vector<Envelope> known_messages(const std::string& node) {
  const Time stamp(12'345'000'000);
  auto frame = std::make_shared<msg::StereoFrame>();
  frame->stamp = stamp;
  frame->left = cv::Mat(3, 4, CV_8UC1);
  frame->right = cv::Mat(3, 4, CV_8UC1);
  for (int i = 0; i < 12; ++i) {
    frame->left.data[i] = static_cast<std::uint8_t>(3 * i);
    frame->right.data[i] = static_cast<std::uint8_t>(200 - i);
  }
  frame->calibration = {4, 3, 304.6710927, 304.6710927, 1.5, 1.25, 0.12};
  auto cloud = std::make_shared<msg::PointCloud>();
  cloud->stamp = stamp;
  auto points = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  points->push_back({1.5f, -2.25f, 7.0f});
  points->push_back({0.125f, 0.25f, 3.5f});
  points->is_dense = true;
  cloud->points = points;
  auto state = std::make_shared<msg::VehicleState>();
  state->stamp = stamp;
  state->position = {1.5, -2.0, 3.25};
  state->velocity = {2.0, 0.5, -0.25};
  state->orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(0.2, 0.3, 1.0).normalized()));
  state->angular_velocity = {0.1, -0.2, 0.3};
  auto detections = std::make_shared<msg::Detections>();
  detections->stamp = stamp;
  detections->items.push_back({{0.1, -0.2, 5.0}, {0.4, 0.3, 0.2}, 57, 0.9});
  auto tracks = std::make_shared<msg::Tracks>();
  tracks->stamp = stamp;
  msg::Track track;
  track.id = 7;
  track.age = 12;
  track.hits = 11;
  track.misses = 1;
  track.state = Eigen::VectorXd::LinSpaced(6, 1.0, 6.0);
  track.covariance = Eigen::MatrixXd::Identity(6, 6) * 0.25;
  track.detection = {0.1, -0.2, 5.0};
  tracks->items = {track};
  tracks->selected_id = 7;
  auto truth = std::make_shared<msg::GroundTruth>();
  truth->stamp = stamp;
  truth->objects.push_back({3, {1, 2, 3}, {0.5, -0.1, 4.0}, {0.3, 0, 0}, true});
  return {envelope<msg::StereoFrame>(frame, node, "frame"),  envelope<msg::PointCloud>(cloud, node, "cloud"),
          envelope<msg::VehicleState>(state, node, "state"), envelope<msg::Detections>(detections, node, "detections"),
          envelope<msg::Tracks>(tracks, node, "tracks"),     envelope<msg::GroundTruth>(truth, node, "truth")};
}

int publish(std::uint32_t domain, double seconds, const std::string& node, const std::string& sent_file) {
  const auto messages = known_messages(node);
  {
    std::ofstream sent(sent_file);
    for (const Envelope& e : messages) {
      const std::string topic = topic_of(e);
      const auto specs = ros2::channels_for(std::string(e.type), topic);
      for (const auto& m : ros2::encode(std::string(e.type), e.payload.get(), topic).messages) {
        const auto& spec = specs.at(m.channel);
        if (spec.derived) continue;
        const ros2::MessageSchema schema(spec.schema, ros2::schema_text(spec.schema));
        sent << nlohmann::ordered_json{{"topic", spec.topic}, {"message", ros2::cdr_to_json(schema, m.cdr)}}.dump()
             << "\n";
      }
    }
  }
  dds::Participant participant(domain);
  dds_bridge::DdsPublication publication(participant, dds::QosTable{}, "", true);
  for (int tick = 0; tick < static_cast<int>(seconds * 10); ++tick) {
    for (const Envelope& e : messages) publication.publish(e);
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  return 0;
}

int failures = 0;
void check(bool ok, const std::string& what) {
  if (!ok) {
    std::fprintf(stderr, "dds_peer_tool expect: %s\n", what.c_str());
    ++failures;
  }
}

// What idl_publisher.c sends.
bool expected_state(const msg::VehicleState& s) {
  const Eigen::Quaterniond q(0.8, 0.0, 0.0, 0.6);
  const Eigen::Vector3d velocity = q * Eigen::Vector3d(1.0, 0.5, -0.25);
  check(s.stamp == Time(12'345'000'000), "state stamp");
  check(s.position == Eigen::Vector3d(1.5, -2.0, 3.25), "state position");
  check(s.orientation.coeffs() == q.coeffs(), "state orientation");
  check((s.velocity - velocity).norm() < 1e-12, "state velocity (the body twist turned into the world)");
  check(s.angular_velocity == Eigen::Vector3d(0.1, -0.2, 0.3), "state angular velocity");
  return true;
}

bool expected_detections(const msg::Detections& d) {
  check(d.stamp == Time(12'345'000'000) && d.frame == "camera", "detections header");
  check(d.items.size() == 1, "one detection");
  if (d.items.size() != 1) return true;
  check(d.items[0].position == Eigen::Vector3d(0.25, -0.5, 6.0), "detection position");
  check(d.items[0].extent == Eigen::Vector3d(0.4, 0.3, 0.2), "detection extent");
  check(d.items[0].point_count == 42 && d.items[0].confidence == 0.875, "detection points and confidence");
  return true;
}

bool expected_tracks(const msg::Tracks& t) {
  check(t.stamp == Time(12'345'000'000), "tracks stamp");
  check(t.items.size() == 1 && t.selected_id == std::optional<std::uint64_t>(9), "one track, selected");
  if (t.items.size() != 1) return true;
  const msg::Track& a = t.items[0];
  check(a.id == 9 && a.age == 30 && a.hits == 28 && a.misses == 2, "track counters");
  Eigen::VectorXd state(6);
  state << 1, 2, 3, 0.5, 0.25, 0.125;
  check(a.state == state, "track state");
  check(a.covariance.rows() == 6 && a.covariance.cols() == 6, "track covariance 6x6");
  if (a.covariance.rows() == 6 && a.covariance.cols() == 6)
    for (int i = 0; i < 36; ++i)
      check(a.covariance(i / 6, i % 6) == ((i % 7 == 0) ? 0.5 : 0.0), "track covariance element " + std::to_string(i));
  check(a.detection == Eigen::Vector3d(0.25, -0.5, 6.0), "track detection");
  return true;
}

bool expected_truth(const msg::GroundTruth& g) {
  check(g.stamp == Time(12'345'000'000), "truth stamp");
  check(g.objects.size() == 1, "one truth object");
  if (g.objects.size() != 1) return true;
  const auto& o = g.objects[0];
  check(o.id == 4 && o.in_view, "truth id and in view");
  check(o.position_world == Eigen::Vector3d(7.0, 0.5, 2.5), "truth world position");
  check(o.position_camera == Eigen::Vector3d(0.25, -0.5, 6.0), "truth camera position");
  check(o.velocity_world == Eigen::Vector3d(-1.0, 0.0, 0.5), "truth velocity");
  return true;
}

int expect(std::uint32_t domain, double timeout_s, const std::string& node) {
  dds::Participant participant(domain);
  dds_bridge::DdsSubscription subscription(participant, dds::QosTable{},
                                           {{"state", "kestrel.VehicleState", "/" + node + "/state"},
                                            {"detections", "kestrel.Detections", "/" + node + "/detections"},
                                            {"tracks", "kestrel.Tracks", "/" + node + "/tracks"},
                                            {"truth", "kestrel.GroundTruth", "/" + node + "/truth"}});
  Logger log("expect");
  std::vector<bool> seen(4, false);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (std::count(seen.begin(), seen.end(), true) < 4 && std::chrono::steady_clock::now() < deadline) {
    subscription.take(log, [&](std::size_t port, std::shared_ptr<const void> m, const dds::WriterMetadata&) {
      if (seen[port]) return;
      seen[port] = true;
      if (port == 0) expected_state(*std::static_pointer_cast<const msg::VehicleState>(m));
      if (port == 1) expected_detections(*std::static_pointer_cast<const msg::Detections>(m));
      if (port == 2) expected_tracks(*std::static_pointer_cast<const msg::Tracks>(m));
      if (port == 3) expected_truth(*std::static_pointer_cast<const msg::GroundTruth>(m));
      std::printf("{\"received\":\"%s\"}\n", subscription.ports()[port].topic.c_str());
    });
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  for (std::size_t p = 0; p < seen.size(); ++p) check(seen[p], "nothing arrived on " + subscription.ports()[p].topic);
  check(subscription.bad_samples() == 0, std::to_string(subscription.bad_samples()) + " samples did not decode");
  return failures == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const std::string mode = argc > 1 ? argv[1] : "";
    if (mode == "publish" && argc == 6)
      return publish(static_cast<std::uint32_t>(std::stoul(argv[2])), std::stod(argv[3]), argv[4], argv[5]);
    if (mode == "expect" && argc == 5)
      return expect(static_cast<std::uint32_t>(std::stoul(argv[2])), std::stod(argv[3]), argv[4]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "dds_peer_tool: %s\n", e.what());
    return 1;
  }
  std::fprintf(stderr, "usage: dds_peer_tool publish DOMAIN SECONDS NODE SENT_JSON | expect DOMAIN TIMEOUT_S NODE\n");
  return 2;
}
