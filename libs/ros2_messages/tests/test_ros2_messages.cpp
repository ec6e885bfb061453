// kestrel's messages as ROS 2 messages: every type round-trips without loss, and every message
// written is exactly what its ros2msg schema says (decoded by the schema alone, as Foxglove does).
#include <gmock/gmock.h>

#include <kestrel/geometry/frames.hpp>
#include <kestrel/messages/actuator_command.hpp>
#include <kestrel/messages/attitude_target.hpp>
#include <kestrel/messages/detections.hpp>
#include <kestrel/messages/ground_truth.hpp>
#include <kestrel/messages/imu.hpp>
#include <kestrel/messages/net_capture.hpp>
#include <kestrel/messages/net_fire.hpp>
#include <kestrel/messages/net_launcher.hpp>
#include <kestrel/messages/point_cloud.hpp>
#include <kestrel/messages/stereo_frame.hpp>
#include <kestrel/messages/tracks.hpp>
#include <kestrel/messages/trajectory_setpoint.hpp>
#include <kestrel/messages/vehicle_state.hpp>
#include <limits>
#include <opencv2/core.hpp>

#include "kestrel/ros2/cdr_json.hpp"
#include "kestrel/ros2/definitions.hpp"
#include "kestrel/ros2_messages/message_mapping.hpp"

using namespace kestrel;
using namespace kestrel::ros2;

namespace {

// Encodes `m` on /node/port, checks each message against its schema, decodes the non-derived
// channels back and returns the kestrel message rebuilt.
template <class T>
std::shared_ptr<const T> round_trip(const T& m, std::vector<nlohmann::ordered_json>* as_json = nullptr) {
  const std::string type(MessageTraits<T>::name);
  const std::string topic = "/node/port";
  const auto channels = channels_for(type, topic);
  const Encoded encoded = encode(type, &m, topic);
  auto decoder = make_decoder(type);
  EXPECT_TRUE(decoder) << type;
  if (!decoder) return nullptr;
  const auto inputs = decoder->inputs();
  std::shared_ptr<const void> rebuilt;
  for (const auto& message : encoded.messages) {
    const ChannelSpec& channel = channels.at(message.channel);
    const MessageSchema schema(channel.schema, schema_text(channel.schema));
    auto json = cdr_to_json(schema, message.cdr);  // throws if the bytes are not that schema
    if (as_json) as_json->push_back(json);
    if (channel.derived) continue;
    std::size_t input = inputs.size();
    for (std::size_t i = 0; i < inputs.size(); ++i)
      if (topic + inputs[i].topic == channel.topic && inputs[i].schema == channel.schema) input = i;
    EXPECT_LT(input, inputs.size()) << channel.topic;
    if (input == inputs.size()) continue;
    auto out = decoder->feed(input, message.cdr, message.sequence.value_or(0), encoded.metadata);
    if (out) {
      EXPECT_FALSE(rebuilt) << "two messages rebuilt from one";
      rebuilt = out;
    }
  }
  EXPECT_TRUE(rebuilt) << type << " was not rebuilt";
  return std::static_pointer_cast<const T>(rebuilt);
}

const double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

TEST(Ros2Messages, EveryEncodableTypeHasADefinitionAndADecoder) {
  for (const std::string& type : encodable_types()) {
    for (const auto& c : channels_for(type, "/a/b")) EXPECT_NO_THROW(MessageSchema(c.schema, schema_text(c.schema)));
    EXPECT_TRUE(make_decoder(type)) << type;
  }
  EXPECT_FALSE(can_encode("test.Unknown"));
  EXPECT_THROW(channels_for("test.Unknown", "/a/b"), Error);
  EXPECT_THAT(schema_text("sensor_msgs/msg/Image"), ::testing::HasSubstr("\nMSG: builtin_interfaces/Time\n"));
}

TEST(Ros2Messages, AStereoFrameIsTwoImagesAndTwoCameraInfosPairedAgainByStampWithItsMountOnTf) {
  msg::StereoFrame f;
  f.stamp = Time(1'500'000'123);
  f.frame_index = 45;
  f.left = cv::Mat(3, 4, CV_8UC1);
  f.right = cv::Mat(3, 4, CV_8UC1);
  for (int i = 0; i < 12; ++i) {
    f.left.data[i] = static_cast<std::uint8_t>(i);
    f.right.data[i] = static_cast<std::uint8_t>(100 + i);
  }
  f.calibration = {4, 3, 304.6710927, 304.6710927, 1.5, 1.25, 0.12};
  f.mount.parent_frame = "hunter";
  f.mount.position = {0.1, -0.0123456789012345, 0.3};
  f.mount.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()));
  std::vector<nlohmann::ordered_json> json;
  auto back = round_trip(f, &json);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->stamp, f.stamp);
  EXPECT_EQ(back->frame_index, 45u);
  EXPECT_EQ(cv::countNonZero(back->left != f.left), 0);
  EXPECT_EQ(cv::countNonZero(back->right != f.right), 0);
  EXPECT_EQ(back->calibration.fx, f.calibration.fx);
  EXPECT_EQ(back->calibration.cy, f.calibration.cy);
  EXPECT_EQ(back->calibration.baseline_m, 0.12);  // bit for bit, through the right P's Tx
  EXPECT_EQ(back->calibration.width, 4);
  EXPECT_EQ(back->mount.parent_frame, "hunter");
  EXPECT_EQ(back->mount.position, f.mount.position);  // bit for bit, through the channels' metadata
  EXPECT_EQ(back->mount.orientation.coeffs(), f.mount.orientation.coeffs());
  ASSERT_EQ(json.size(), 5u);
  const auto& tf = json[4]["transforms"][0];  // viewers place the camera on the vehicle
  EXPECT_EQ(tf["header"]["frame_id"], "hunter");
  EXPECT_EQ(tf["child_frame_id"], "camera");
  EXPECT_EQ(tf["transform"]["translation"]["z"], 0.3);
  EXPECT_EQ(tf["transform"]["rotation"]["w"], f.mount.orientation.w());
  EXPECT_EQ(json[0]["encoding"], "mono8");
  EXPECT_EQ(json[0]["header"]["stamp"]["sec"], 1);
  EXPECT_EQ(json[0]["header"]["stamp"]["nanosec"], 500000123);
  EXPECT_NEAR(json[3]["p"][3].get<double>(), -304.6710927 * 0.12, 1e-12);

  f.left = cv::Mat(3, 4, CV_16UC1);
  f.right = cv::Mat(3, 4, CV_16UC1);
  EXPECT_THROW(encode("kestrel.StereoFrame", &f, "/cam/frame"), Error);
}

TEST(Ros2Messages, AnImuIsSensorMsgsImuAndItsMagneticFieldPairedByStamp) {
  msg::Imu m;
  m.stamp = Time(2'000'000'017);
  m.frame = "ocams_imu";
  m.angular_velocity = {0.01, -0.02, 0.5};
  m.linear_acceleration = {0.1, 0.2, 9.81};
  m.gravity_removed = true;
  m.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Eigen::Vector3d(0, 0.6, 0.8)));
  m.magnetic_field = Eigen::Vector3d(39e-6, 0.5e-6, -25e-6);
  std::vector<nlohmann::ordered_json> json;
  auto back = round_trip(m, &json);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->stamp, m.stamp);
  EXPECT_EQ(back->frame, "ocams_imu");
  EXPECT_EQ(back->angular_velocity, m.angular_velocity);
  EXPECT_EQ(back->linear_acceleration, m.linear_acceleration);
  EXPECT_TRUE(back->gravity_removed);
  ASSERT_TRUE(back->orientation && back->magnetic_field);
  EXPECT_EQ(back->orientation->coeffs(), m.orientation->coeffs());
  EXPECT_EQ(*back->magnetic_field, *m.magnetic_field);
  ASSERT_EQ(json.size(), 2u);
  EXPECT_EQ(json[0]["orientation_covariance"][0], 0.0);

  msg::Imu bare;  // no orientation, no magnetometer: one message, covariance -1 as the type says
  bare.linear_acceleration = {0, 0, 9.8};
  json.clear();
  auto bare_back = round_trip(bare, &json);
  ASSERT_TRUE(bare_back);
  EXPECT_FALSE(bare_back->orientation);
  EXPECT_FALSE(bare_back->magnetic_field);
  ASSERT_EQ(json.size(), 1u);
  EXPECT_EQ(json[0]["orientation_covariance"][0], -1.0);
}

TEST(Ros2Messages, TheDefaultMountIsALevelCameraLookingAlongItsParentsX) {
  const msg::CameraMount m;
  EXPECT_TRUE(m.orientation.toRotationMatrix().isApprox(geometry::body_from_camera(), 1e-15));
  EXPECT_TRUE((m.orientation * Eigen::Vector3d::UnitZ()).isApprox(Eigen::Vector3d::UnitX()));
}

TEST(Ros2Messages, ACloudIsAPointCloud2OfFloatXyzWithItsPixelsPerPointInTheChannel) {
  msg::PointCloud c;
  c.stamp = Time(-7);  // before the run's start: still exact
  auto points = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  points->push_back({1.5f, -2.25f, 7.0f});
  points->push_back({0.1f, 0.2f, 0.3f});
  points->is_dense = true;
  c.points = points;
  c.pixels_per_point = 2;
  c.focal_baseline_px_m = 36.48;
  auto back = round_trip(c);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->stamp, c.stamp);
  EXPECT_EQ(back->frame, "camera");
  EXPECT_EQ(back->pixels_per_point, 2);
  EXPECT_EQ(back->focal_baseline_px_m, 36.48);
  ASSERT_EQ(back->points->size(), 2u);
  EXPECT_EQ(back->points->points[0].y, -2.25f);
  EXPECT_EQ(back->points->points[1].z, 0.3f);
  EXPECT_TRUE(back->points->is_dense);
}

TEST(Ros2Messages, DetectionsTracksAndTruthRoundTripWithMarkersForViewers) {
  msg::Detections d;
  d.stamp = Time(33'000'000);
  d.items.push_back({{0.1, -0.2, 5.0}, {0.4, 0.3, 0.2}, 57, 0.9});
  std::vector<nlohmann::ordered_json> json;
  auto dback = round_trip(d, &json);
  ASSERT_TRUE(dback);
  ASSERT_EQ(dback->items.size(), 1u);
  EXPECT_EQ(dback->items[0].position, d.items[0].position);
  EXPECT_EQ(dback->items[0].extent, d.items[0].extent);
  EXPECT_EQ(dback->items[0].point_count, 57);
  EXPECT_EQ(dback->items[0].confidence, 0.9);
  ASSERT_EQ(json.size(), 2u);
  EXPECT_EQ(json[1]["markers"].size(), 2u);  // DELETEALL, then the cube
  EXPECT_EQ(json[1]["markers"][1]["type"], 1);

  msg::Tracks t;
  t.stamp = Time(66'000'000);
  msg::Track a;
  a.id = 7;
  a.age = 12;
  a.hits = 11;
  a.misses = 1;
  a.state = Eigen::VectorXd::LinSpaced(9, 1.0, 9.0);
  a.covariance = Eigen::MatrixXd::Random(9, 9);
  msg::Track b = a;
  b.id = 8;
  b.detection = {1, 2, 3};
  t.items = {a, b};
  t.selected_id = 8;
  auto tback = round_trip(t);
  ASSERT_TRUE(tback);
  ASSERT_EQ(tback->items.size(), 2u);
  EXPECT_EQ(tback->items[0].state, a.state);
  EXPECT_EQ(tback->items[0].covariance, a.covariance);
  EXPECT_TRUE(tback->items[0].detection.array().isNaN().all());  // coasting: NaN stays NaN
  EXPECT_EQ(tback->items[1].detection, b.detection);
  EXPECT_EQ(tback->selected_id, std::optional<std::uint64_t>(8));
  t.selected_id.reset();
  EXPECT_FALSE(round_trip(t)->selected_id);

  msg::GroundTruth g;
  g.stamp = Time(99);
  g.objects.push_back({3, {1, 2, 3}, {0.5, -0.1, 4.0}, {0.3, 0, 0}, false});
  auto gback = round_trip(g);
  ASSERT_TRUE(gback);
  ASSERT_EQ(gback->objects.size(), 1u);
  EXPECT_EQ(gback->objects[0].id, 3u);
  EXPECT_EQ(gback->objects[0].position_camera, g.objects[0].position_camera);
  EXPECT_FALSE(gback->objects[0].in_view);
}

TEST(Ros2Messages, AVehicleStateIsOdometryWithItsTwistInTheBodyFrameAndATransform) {
  msg::VehicleState s;
  s.stamp = Time(5);
  s.position = {1, 2, 3};
  s.velocity = {2.0, 0.5, -0.25};
  s.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(0.2, 0.3, 1.0).normalized()));
  s.angular_velocity = {0.1, -0.2, 0.3};
  std::vector<nlohmann::ordered_json> json;
  auto back = round_trip(s, &json);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->position, s.position);
  EXPECT_EQ(back->orientation.coeffs(), s.orientation.coeffs());
  EXPECT_LT((back->velocity - s.velocity).norm(), 1e-14);  // rotated into the body and back
  EXPECT_EQ(back->angular_velocity, s.angular_velocity);
  ASSERT_EQ(json.size(), 2u);
  EXPECT_EQ(json[0]["child_frame_id"], "node");
  const Eigen::Vector3d body = s.orientation.conjugate() * s.velocity;
  EXPECT_DOUBLE_EQ(json[0]["twist"]["twist"]["linear"]["x"].get<double>(), body.x());
  EXPECT_EQ(json[1]["transforms"][0]["child_frame_id"], "node");
  EXPECT_EQ(channels_for("kestrel.VehicleState", "/hunter/state")[1].topic, "/tf");
}

TEST(Ros2Messages, ControlMessagesRoundTrip) {
  msg::TrajectorySetpoint sp{Time(1), {1, 2, 3}, {4, 5, 6}, {7, 8, 9}, 0.5, -0.1};
  auto spb = round_trip(sp);
  EXPECT_EQ(spb->acceleration, sp.acceleration);
  EXPECT_EQ(spb->yaw_rate, -0.1);
  msg::ActuatorCommand ac{Time(2), 14.7, {0.1, 0.2, 0.3}, {500, 510, 520, 530, 540, 550}};
  auto acb = round_trip(ac);
  EXPECT_EQ(acb->rotor_speeds_rad_s, ac.rotor_speeds_rad_s);
  EXPECT_EQ(acb->torque_nm, ac.torque_nm);
  msg::AttitudeTarget at{Time(3), Eigen::Quaterniond(0.9, 0.1, 0.2, 0.3).normalized(), {1, 2, 3}, 15.0, 14.7};
  auto atb = round_trip(at);
  EXPECT_EQ(atb->orientation.coeffs(), at.orientation.coeffs());
  EXPECT_EQ(atb->hover_thrust_n, 14.7);
  msg::NetFire nf{Time(4), 9, {0.1, kNaN, 0.3}};
  auto nfb = round_trip(nf);
  EXPECT_EQ(nfb->target_id, 9u);
  EXPECT_TRUE(std::isnan(nfb->aim_error_m.y()));
  msg::NetCapture nc{Time(5), 2, {4, 5, 6}};
  EXPECT_EQ(round_trip(nc)->position_world, nc.position_world);
  msg::NetLauncher nl{Time(6), 1, 1, Time(1'500'000'000)};
  const auto nlb = round_trip(nl);
  EXPECT_EQ(nlb->nets_left, 1);
  EXPECT_EQ(nlb->nets_used, 1);
  EXPECT_EQ(nlb->ready_at, nl.ready_at);
}

TEST(Ros2Messages, BytesThatAreNotTheTypeGiveAnErrorNotACrash) {
  auto decoder = make_decoder("kestrel.Detections");
  const std::vector<std::uint8_t> short_message = {0, 1, 0, 0, 1, 0};
  EXPECT_THROW(decoder->feed(0, short_message, 0, {}), Error);
  std::vector<std::uint8_t> huge_count = {0, 1, 0, 0, 0, 0, 0, 0, 0,    0,    0,    0,
                                          1, 0, 0, 0, 0, 0, 0, 0, 0xFF, 0xFF, 0xFF, 0x7F};
  EXPECT_THROW(decoder->feed(0, huge_count, 0, {}), Error);
}
