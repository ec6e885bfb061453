// The `dds_bridge` node: kestrel's outputs on DDS topics, and DDS topics on its ports, as ROS 2
// writes and reads them (docs/ros2.md): topic "rt/NAME", types "pkg::msg::dds_::Type_", XCDR1,
// ROS 2's default QoS. A ROS 2 node subscribes to a kestrel graph, and a graph split between the
// vehicle and the ground runs as two processes over DDS.
#include <fmt/format.h>

#include <kestrel/dds/ros2_names.hpp>
#include <kestrel/messages/detections.hpp>
#include <kestrel/messages/ground_truth.hpp>
#include <kestrel/messages/imu.hpp>
#include <kestrel/messages/point_cloud.hpp>
#include <kestrel/messages/stereo_frame.hpp>
#include <kestrel/messages/tracks.hpp>
#include <kestrel/messages/vehicle_state.hpp>
#include <kestrel/plugin.hpp>

#include "dds_publication.hpp"
#include "dds_subscription.hpp"

namespace kestrel::dds_bridge {

struct DdsBridgeConfig {
  std::int64_t domain_id = 0;
  std::string publish = "!*";
  std::string prefix;
  bool derived = true;
  std::string frame_topic, truth_topic, cloud_topic, detections_topic, tracks_topic, state_topic, imu_topic;
  dds::Reliability reliability = dds::Reliability::reliable;
  std::int64_t depth = 10;
  dds::Durability durability = dds::Durability::volatile_;
  std::string qos_overrides;
  double poll_rate_hz = 500.0;
  bool restamp = true;
  bool end_with_writers = false;
};

// The system time, in ns since the epoch, at which this run's clock read zero. The realtime
// executor's clock is the steady clock from the run's start; two processes on one machine (or
// machines whose clocks agree, by NTP or PTP) agree on the system time.
std::int64_t clock_origin_ns(Time now) {
  const auto system =
      std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch());
  return system.count() - std::chrono::duration_cast<std::chrono::nanoseconds>(now).count();
}

// A copy of `message` with its stamp moved by `offset`.
template <class T>
std::shared_ptr<const void> restamped(const std::shared_ptr<const void>& message, Time offset) {
  auto copy = std::make_shared<T>(*std::static_pointer_cast<const T>(message));
  copy->stamp += offset;
  return copy;
}

class DdsBridgeNode final : public Node {
 public:
  static constexpr Input<AnyMessage> kIn{"in"};
  static constexpr Output<msg::StereoFrame> kFrame{"frame"};
  static constexpr Output<msg::GroundTruth> kTruth{"truth"};
  static constexpr Output<msg::PointCloud> kCloud{"cloud"};
  static constexpr Output<msg::Detections> kDetections{"detections"};
  static constexpr Output<msg::Tracks> kTracks{"tracks"};
  static constexpr Output<msg::VehicleState> kState{"state"};
  static constexpr Output<msg::Imu> kImu{"imu"};

  static NodeSpec spec() {
    using C = DdsBridgeConfig;
    ConfigSpec<C> c;
    c.param("domain_id", &C::domain_id).range(0, 232).describe("the DDS domain (ROS_DOMAIN_ID)");
    c.param("publish", &C::publish)
        .describe(
            "the outputs published: topic patterns /NODE/PORT separated by commas or spaces ('*' for every "
            "output, '!PATTERN' to leave some out); '' for every connected output but point clouds, as --record "
            "records; '!*' (the default): none");
    c.param("prefix", &C::prefix)
        .describe("put before every published topic name, as a ROS 2 namespace (/vehicle: /vehicle/tracker/tracks)");
    c.param("derived", &C::derived)
        .describe("also publish the channels made for viewers (markers, /tf), which rviz2 shows");
    c.param("frame_topic", &C::frame_topic)
        .describe("ROS 2 topic of the stereo frames for `frame` (its /left, /right and camera infos); empty: none");
    c.param("truth_topic", &C::truth_topic).describe("ROS 2 topic of the ground truth for `truth`; empty: none");
    c.param("cloud_topic", &C::cloud_topic).describe("ROS 2 topic of the point clouds for `cloud`; empty: none");
    c.param("detections_topic", &C::detections_topic)
        .describe("ROS 2 topic of the detections for `detections`; empty: none");
    c.param("tracks_topic", &C::tracks_topic).describe("ROS 2 topic of the tracks for `tracks`; empty: none");
    c.param("state_topic", &C::state_topic)
        .describe("ROS 2 topic of the vehicle states (nav_msgs/Odometry) for `state`; empty: none");
    c.param("imu_topic", &C::imu_topic).describe("ROS 2 topic of the inertial measurements for `imu`; empty: none");
    c.choice("reliability", &C::reliability,
             {{"reliable", dds::Reliability::reliable}, {"best_effort", dds::Reliability::best_effort}})
        .describe("every topic's reliability unless qos_overrides says otherwise (ROS 2's default: reliable)");
    c.param("depth", &C::depth).range(1, 100000).describe("keep last this many samples (ROS 2's default: 10)");
    c.choice("durability", &C::durability,
             {{"volatile", dds::Durability::volatile_}, {"transient_local", dds::Durability::transient_local}})
        .describe("volatile, or transient_local: a late reader gets the last `depth` samples (static data)");
    c.param("qos_overrides", &C::qos_overrides)
        .describe(
            "per-topic QoS: 'PATTERN: WORDS; PATTERN: WORDS', words among reliable, best_effort, volatile, "
            "transient_local, depth=N; patterns are globs on the ROS 2 topic, applied in order");
    c.param("restamp", &C::restamp)
        .describe(
            "put received stamps on this run's clock (realtime runs announce when their clock read zero), so that "
            "latencies measured here count from the capture in the other process; off: stamps as sent");
    c.param("end_with_writers", &C::end_with_writers)
        .describe(
            "end the stream once every subscribed topic has had a writer and none has one any more (the other "
            "process's run ended), after taking what they sent: a ground run ends with the vehicle's");
    c.param("poll_rate_hz", &C::poll_rate_hz)
        .with_unit("Hz")
        .range(1.0, 10000.0)
        .describe("how often subscribed topics are read: the most a message waits after it arrives is one period");
    return NodeSpec("dds_bridge", "Publishes outputs on DDS topics and subscribes to DDS topics, as ROS 2 does")
        .details(
            "Each tapped message becomes the ROS 2 messages a recording holds (docs/recording.md), written on "
            "DDS topic 'rt' + /NODE/PORT (after the prefix) with the ROS 2 type's DDS name, XCDR1, and the QoS "
            "given; a ROS 2 Humble node (rmw_cyclonedds_cpp or rmw_fastrtps_cpp) subscribes to them as to "
            "any topic. Each port with a topic reads the DDS topics its message is made of and publishes the "
            "kestrel message rebuilt from them (subscribing needs the realtime executor). Cyclone DDS reads "
            "its network settings from CYCLONEDDS_URI. A sample that does not decode is counted and dropped.")
        .tap(kIn, "the outputs `publish` selects (or that a graph connects to it)",
             TapOptions{"publish", {"kestrel.PointCloud"}})
        .output(kFrame, "stereo frames read from frame_topic")
        .output(kTruth, "ground truth read from truth_topic")
        .output(kCloud, "point clouds read from cloud_topic")
        .output(kDetections, "detections read from detections_topic")
        .output(kTracks, "tracks read from tracks_topic")
        .output(kState, "vehicle states read from state_topic")
        .output(kImu, "inertial measurements read from imu_topic")
        .config(std::move(c))
        .needs_executor_when(
            ExecutorNeed::realtime, "it subscribes to DDS topics (what arrives is not in lockstep)",
            [](const Params& p) {
              for (const char* topic : {"frame_topic", "truth_topic", "cloud_topic", "detections_topic", "tracks_topic",
                                        "state_topic", "imu_topic"})
                if (p.contains(topic) && !p.get<std::string>(topic).empty()) return true;
              return false;
            });
  }

  explicit DdsBridgeNode(NodeInit& init)
      : cfg_(init.config<DdsBridgeConfig>()),
        qos_(dds::Qos{cfg_.reliability, static_cast<std::int32_t>(cfg_.depth), cfg_.durability}, cfg_.qos_overrides),
        participant_(static_cast<std::uint32_t>(cfg_.domain_id)),
        publication_(participant_, qos_, cfg_.prefix, cfg_.derived) {
    realtime_ = init.realtime();
    if (!cfg_.prefix.empty()) dds::ros2_dds_topic(cfg_.prefix);  // refused now, not at the first message
    auto ports = subscribed_ports(cfg_);
    if (!ports.empty()) {
      subscription_ = std::make_unique<DdsSubscription>(participant_, qos_, std::move(ports));
      init.set_rate(cfg_.poll_rate_hz);
    }
  }

  void process(Context& ctx) override {
    // Only a realtime run's clock is tied to the system's; a lockstep run's is simulated.
    if (realtime_ && !publication_.has_clock_origin()) publication_.set_clock_origin(clock_origin_ns(ctx.now()));
    publication_.publish(ctx.envelope(kIn.name));
  }

  void tick(Context& ctx) override {
    if (!subscription_) return;
    if (!own_origin_ns_) own_origin_ns_ = clock_origin_ns(ctx.now());
    // Asked before taking: what a writer sent before it left is taken below, then the stream ends.
    const bool gone = cfg_.end_with_writers && subscription_->writers_gone();
    take(ctx);
    if (gone) ctx.end_of_stream();
  }

  void finish(Context& ctx) override {
    ReportSection section;
    section.quantity("domain_id", cfg_.domain_id);
    publication_.report(section);
    std::string received;
    if (subscription_) {
      if (own_origin_ns_) take(ctx);
      subscription_->report(section);
      section.info("restamped", restamped_);
      for (const auto& topic : subscription_->never_matched())
        ctx.log().warn("no DDS writer of {} was ever found (another domain, type or QoS?)", topic);
      received = fmt::format(", received {} messages ({} samples that did not decode)", received_,
                             subscription_->bad_samples());
    }
    ctx.set_report_section(ctx.id(), section.markdown(fmt::format("DDS domain {}: published {} samples{}.\n",
                                                                  cfg_.domain_id, publication_.samples(), received)));
  }

 private:
  static std::vector<SubscribedPort> subscribed_ports(const DdsBridgeConfig& c) {
    std::vector<SubscribedPort> out;
    auto add = [&](const char* port, std::string_view type, const std::string& topic) {
      if (!topic.empty()) out.push_back({port, std::string(type), topic});
    };
    add("frame", MessageTraits<msg::StereoFrame>::name, c.frame_topic);
    add("truth", MessageTraits<msg::GroundTruth>::name, c.truth_topic);
    add("cloud", MessageTraits<msg::PointCloud>::name, c.cloud_topic);
    add("detections", MessageTraits<msg::Detections>::name, c.detections_topic);
    add("tracks", MessageTraits<msg::Tracks>::name, c.tracks_topic);
    add("state", MessageTraits<msg::VehicleState>::name, c.state_topic);
    add("imu", MessageTraits<msg::Imu>::name, c.imu_topic);
    return out;
  }

  template <class T>
  void send(Context& ctx, const Output<T>& port, std::shared_ptr<const void> message) {
    ctx.publish(port, std::static_pointer_cast<const T>(std::move(message)));
  }

  void take(Context& ctx) {
    subscription_->take(
        ctx.log(), [&](std::size_t port, std::shared_ptr<const void> message, const dds::WriterMetadata& metadata) {
          publish(ctx, subscription_->ports().at(port).port, std::move(message), stamp_offset(metadata));
        });
  }

  // How far the writer's clock is behind this run's: its origin minus ours.
  Time stamp_offset(const dds::WriterMetadata& metadata) {
    if (!cfg_.restamp || !own_origin_ns_) return Time(0);
    const auto it = metadata.find(kClockOriginKey);
    if (it == metadata.end()) return Time(0);
    try {
      const Time offset(std::stoll(it->second) - *own_origin_ns_);
      restamped_ = true;
      return offset;
    } catch (const std::exception&) {
      return Time(0);  // not a number: stamps as sent
    }
  }

  void publish(Context& ctx, const std::string& port, std::shared_ptr<const void> message, Time offset) {
    ++received_;
    if (offset != Time(0)) message = restamp(port, message, offset);
    if (port == "frame") return send(ctx, kFrame, std::move(message));
    if (port == "truth") return send(ctx, kTruth, std::move(message));
    if (port == "cloud") return send(ctx, kCloud, std::move(message));
    if (port == "detections") return send(ctx, kDetections, std::move(message));
    if (port == "tracks") return send(ctx, kTracks, std::move(message));
    if (port == "imu") return send(ctx, kImu, std::move(message));
    send(ctx, kState, std::move(message));
  }

  static std::shared_ptr<const void> restamp(const std::string& port, const std::shared_ptr<const void>& m,
                                             Time offset) {
    if (port == "frame") return restamped<msg::StereoFrame>(m, offset);
    if (port == "truth") return restamped<msg::GroundTruth>(m, offset);
    if (port == "cloud") return restamped<msg::PointCloud>(m, offset);
    if (port == "detections") return restamped<msg::Detections>(m, offset);
    if (port == "tracks") return restamped<msg::Tracks>(m, offset);
    if (port == "imu") return restamped<msg::Imu>(m, offset);
    return restamped<msg::VehicleState>(m, offset);
  }

  DdsBridgeConfig cfg_;
  bool realtime_ = false;
  std::optional<std::int64_t> own_origin_ns_;
  bool restamped_ = false;
  dds::QosTable qos_;
  dds::Participant participant_;
  DdsPublication publication_;
  std::unique_ptr<DdsSubscription> subscription_;
  std::uint64_t received_ = 0;
};
KESTREL_REGISTER_NODE(DdsBridgeNode)

}  // namespace kestrel::dds_bridge
