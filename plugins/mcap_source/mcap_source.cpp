// The `mcap_source` node: replays the channels of an MCAP file (kestrel's recordings, ROS 2 bags
// of the supported standard types) on its ports, each port fed from the topic a parameter names.
// It ticks at the recording's rate, so that under lockstep every message comes out at the very
// time it was logged and a replayed chain computes what the live one did; under realtime that
// is the recorded pace.
#include <fmt/format.h>

#include <kestrel/messages/detections.hpp>
#include <kestrel/messages/ground_truth.hpp>
#include <kestrel/messages/imu.hpp>
#include <kestrel/messages/point_cloud.hpp>
#include <kestrel/messages/stereo_frame.hpp>
#include <kestrel/messages/tracks.hpp>
#include <kestrel/messages/vehicle_state.hpp>
#include <kestrel/plugin.hpp>

#include "recorded_channels.hpp"

namespace kestrel::replay {

struct McapSourceConfig {
  std::string file;
  std::string frame_topic, truth_topic, cloud_topic, detections_topic, tracks_topic, state_topic, imu_topic;
  // A ROS 2 bag's stereo topics, where they are not named after frame_topic.
  std::string left_topic, right_topic, left_info_topic, right_info_topic;
  double rate_hz = 0.0;
};

class McapSourceNode final : public Node {
 public:
  static constexpr Output<msg::StereoFrame> kFrame{"frame"};
  static constexpr Output<msg::GroundTruth> kTruth{"truth"};
  static constexpr Output<msg::PointCloud> kCloud{"cloud"};
  static constexpr Output<msg::Detections> kDetections{"detections"};
  static constexpr Output<msg::Tracks> kTracks{"tracks"};
  static constexpr Output<msg::VehicleState> kState{"state"};
  static constexpr Output<msg::Imu> kImu{"imu"};

  static NodeSpec spec() {
    using C = McapSourceConfig;
    ConfigSpec<C> c;
    c.required("file", &C::file).describe("the MCAP file replayed");
    c.param("frame_topic", &C::frame_topic)
        .describe("recorded StereoFrame output for `frame` (its /left, /right and camera infos); empty: none");
    c.param("left_topic", &C::left_topic)
        .describe(
            "sensor_msgs/msg/Image topic of rectified left images for `frame`, in a bag whose topics are not "
            "frame_topic/left, ... (/stereo/left/image_rect); with right_topic, left_info_topic and right_info_topic");
    c.param("right_topic", &C::right_topic).describe("rectified right images for `frame`, with left_topic");
    c.param("left_info_topic", &C::left_info_topic)
        .describe("sensor_msgs/msg/CameraInfo of the left camera for `frame` (/stereo/left/camera_info)");
    c.param("right_info_topic", &C::right_info_topic)
        .describe("sensor_msgs/msg/CameraInfo of the right camera for `frame`; its P gives the baseline");
    c.rule("left_topic, right_topic, left_info_topic and right_info_topic are set together, instead of frame_topic",
           {"left_topic", "right_topic", "left_info_topic", "right_info_topic", "frame_topic"}, [](const C& k) {
             const int set = !k.left_topic.empty() + !k.right_topic.empty() + !k.left_info_topic.empty() +
                             !k.right_info_topic.empty();
             return set == 0 || (set == 4 && k.frame_topic.empty());
           });
    c.param("truth_topic", &C::truth_topic).describe("kestrel_msgs/msg/GroundTruth topic for `truth`; empty: none");
    c.param("cloud_topic", &C::cloud_topic).describe("sensor_msgs/msg/PointCloud2 topic for `cloud`; empty: none");
    c.param("detections_topic", &C::detections_topic)
        .describe("kestrel_msgs/msg/Detections topic for `detections`; empty: none");
    c.param("tracks_topic", &C::tracks_topic).describe("kestrel_msgs/msg/Tracks topic for `tracks`; empty: none");
    c.param("state_topic", &C::state_topic).describe("nav_msgs/msg/Odometry topic for `state`; empty: none");
    c.param("imu_topic", &C::imu_topic)
        .describe("sensor_msgs/msg/Imu topic for `imu` (with its /mag MagneticField where recorded); empty: none");
    c.param("rate_hz", &C::rate_hz)
        .with_unit("Hz")
        .range(0.0, 1e6)
        .describe(
            "how often the node publishes what was logged since its last tick; 0: the busiest replayed "
            "channel's recorded rate, so that ticks fall on the logged times");
    c.requirement("some port has a topic: frame_topic (or left_topic, ...), truth_topic, ... name what to replay",
                  {"frame_topic", "left_topic", "truth_topic", "cloud_topic", "detections_topic", "tracks_topic",
                   "state_topic", "imu_topic"},
                  [](const C& k) {
                    return !(k.frame_topic + k.left_topic + k.truth_topic + k.cloud_topic + k.detections_topic +
                             k.tracks_topic + k.state_topic + k.imu_topic)
                                .empty();
                  });
    return NodeSpec("mcap_source", "Replays channels of an MCAP recording or ROS 2 bag on its ports")
        .details(
            "Each port with a topic publishes the kestrel messages rebuilt from that topic's ROS 2 messages "
            "(docs/recording.md), at the time they were logged, in log-time order. A StereoFrame is paired "
            "again from its images and camera infos by stamp. The run ends after the last message.")
        .output(kFrame, "stereo frames")
        .output(kTruth, "ground truth")
        .output(kCloud, "point clouds")
        .output(kDetections, "detections")
        .output(kTracks, "tracks")
        .output(kState, "vehicle states")
        .output(kImu, "inertial measurements")
        .config(std::move(c));
  }

  explicit McapSourceNode(NodeInit& init) : cfg_(init.config<McapSourceConfig>()), channels_(cfg_.file, ports(cfg_)) {
    const double rate = cfg_.rate_hz > 0 ? cfg_.rate_hz : channels_.busiest_rate_hz();
    if (!(rate > 0))
      throw Error("cannot tell the recording's rate (fewer than two messages on every port's channels); set rate_hz");
    init.set_rate(rate);
  }

  void tick(Context& ctx) override {
    const auto now = static_cast<mcap::Timestamp>(std::max<std::int64_t>(0, ctx.now().count()));
    channels_.replay(next_, now + 1, [&](std::size_t port, std::shared_ptr<const void> message) {
      publish(ctx, port, std::move(message));
    });
    next_ = now + 1;
    if (next_ > channels_.end_time()) ctx.end_of_stream();
  }

  void finish(Context& ctx) override {
    ctx.set_report_section(ctx.id(),
                           ReportSection()
                               .info("file", cfg_.file)
                               .quantity("published", published_, "messages")
                               .metric("unpaired", channels_.unpaired(), "messages", Better::lower)
                               .info("problems", channels_.problems())
                               .markdown(fmt::format("Replayed {} messages from `{}`.\n", published_, cfg_.file)));
  }

 private:
  static std::vector<ReplayedPort> ports(const McapSourceConfig& c) {
    std::vector<ReplayedPort> out;
    auto add = [&](const char* port, std::string_view type, const std::string& topic) {
      if (!topic.empty()) out.push_back({port, std::string(type), topic});
    };
    if (!c.left_topic.empty())
      out.push_back({"frame",
                     std::string(MessageTraits<msg::StereoFrame>::name),
                     c.left_topic,
                     {c.left_topic, c.right_topic, c.left_info_topic, c.right_info_topic}});
    add("frame", MessageTraits<msg::StereoFrame>::name, c.frame_topic);
    add("truth", MessageTraits<msg::GroundTruth>::name, c.truth_topic);
    add("cloud", MessageTraits<msg::PointCloud>::name, c.cloud_topic);
    add("detections", MessageTraits<msg::Detections>::name, c.detections_topic);
    add("tracks", MessageTraits<msg::Tracks>::name, c.tracks_topic);
    add("state", MessageTraits<msg::VehicleState>::name, c.state_topic);
    add("imu", MessageTraits<msg::Imu>::name, c.imu_topic);
    return out;  // not empty: the spec's rule
  }

  template <class T>
  void send(Context& ctx, const Output<T>& port, std::shared_ptr<const void> message) {
    ctx.publish(port, std::static_pointer_cast<const T>(std::move(message)));
  }

  void publish(Context& ctx, std::size_t index, std::shared_ptr<const void> message) {
    ++published_;
    const std::string& port = channels_.ports().at(index).port;
    if (port == "frame") return send(ctx, kFrame, std::move(message));
    if (port == "truth") return send(ctx, kTruth, std::move(message));
    if (port == "cloud") return send(ctx, kCloud, std::move(message));
    if (port == "detections") return send(ctx, kDetections, std::move(message));
    if (port == "tracks") return send(ctx, kTracks, std::move(message));
    if (port == "imu") return send(ctx, kImu, std::move(message));
    send(ctx, kState, std::move(message));
  }

  McapSourceConfig cfg_;
  RecordedChannels channels_;
  mcap::Timestamp next_ = 0;
  std::uint64_t published_ = 0;
};
KESTREL_REGISTER_NODE(McapSourceNode)

}  // namespace kestrel::replay
