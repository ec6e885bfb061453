// The `tracker` node in a graph, with its components named in YAML, fed by a replay source whose
// detections (and their stamps) the test chooses; a probe puts the tracks into the report.
#include <gmock/gmock.h>

#include <cmath>
#include <kestrel/plugin.hpp>
#include <string>
#include <vector>

#include "kestrel/geometry/frames.hpp"
#include "kestrel/messages/detections.hpp"
#include "kestrel/messages/tracks.hpp"
#include "kestrel/messages/vehicle_state.hpp"
#include "kestrel/runtime/graph.hpp"
#include "kestrel/runtime/plugin_host.hpp"
#include "kestrel/runtime/run.hpp"
#include "kestrel/testing/plugins.hpp"

using namespace kestrel;

namespace {

struct ReplayConfig {
  std::vector<double> stamps_s;        ///< capture time of each frame
  std::vector<double> starts_m;        ///< x y z of each target at t = 0
  std::vector<double> velocities_m_s;  ///< vx vy vz of each target
};

// One frame per tick: the targets' exact positions at the frame's stamp.
class DetectionReplay final : public Node {
 public:
  static constexpr Output<msg::Detections> kOut{"detections"};
  static NodeSpec spec() {
    ConfigSpec<ReplayConfig> c;
    c.param("stamps_s", &ReplayConfig::stamps_s).describe("capture time of each frame");
    c.param("starts_m", &ReplayConfig::starts_m).describe("x y z of each target at t = 0");
    c.param("velocities_m_s", &ReplayConfig::velocities_m_s).describe("vx vy vz of each target");
    return NodeSpec("detection_replay", "Detections of targets moving at constant velocity, at given stamps")
        .output(kOut, "detections")
        .config(std::move(c));
  }
  explicit DetectionReplay(NodeInit& init) : cfg_(init.config<ReplayConfig>()) { init.set_rate(30.0); }
  void tick(Context& ctx) override {
    const double t = cfg_.stamps_s.at(next_);
    msg::Detections out;
    out.stamp = from_seconds(t);
    for (std::size_t i = 0; i + 2 < cfg_.starts_m.size(); i += 3) {
      msg::Detection d;
      for (std::size_t a = 0; a < 3; ++a)
        d.position(static_cast<Eigen::Index>(a)) = cfg_.starts_m[i + a] + cfg_.velocities_m_s[i + a] * t;
      out.items.push_back(d);
    }
    ctx.publish(kOut, std::move(out));
    if (++next_ == cfg_.stamps_s.size()) ctx.end_of_stream();
  }

 private:
  ReplayConfig cfg_;
  std::size_t next_ = 0;
};

// A hunter hovering 3 m up that pitches back and forth (0.3 rad at 1.5 Hz), its camera 0.1 m ahead of
// its centre, seeing a target that hangs still at (6, 0.5, 3.5): the target's detections, in the
// camera frame, and the hunter's states, each published a frame ahead of the detections it takes to
// the world.
class PitchingCamera final : public Node {
 public:
  static constexpr Output<msg::Detections> kDetections{"detections"};
  static constexpr Output<msg::VehicleState> kPose{"pose"};
  static NodeSpec spec() {
    return NodeSpec("pitching_camera", "A still target seen from a pitching hunter, and the hunter's states")
        .output(kDetections, "the target, camera frame")
        .output(kPose, "the hunter's state, a frame ahead");
  }
  explicit PitchingCamera(NodeInit& init) { init.set_rate(30.0); }
  static msg::VehicleState state(double t) {
    msg::VehicleState s;
    s.stamp = from_seconds(t);
    s.position = Eigen::Vector3d(0.0, 0.0, 3.0);
    s.orientation =
        Eigen::Quaterniond(Eigen::AngleAxisd(0.3 * std::sin(2.0 * M_PI * 1.5 * t), Eigen::Vector3d::UnitY()));
    return s;
  }
  void tick(Context& ctx) override {
    const double t = next_ / 30.0;
    if (next_ == 0) ctx.publish(kPose, state(t));
    ctx.publish(kPose, state(t + 1.0 / 30.0));
    const msg::VehicleState now = state(t);
    const auto camera = geometry::camera_on_body(now.position, now.orientation, Eigen::Vector3d(0.1, 0.0, 0.0));
    msg::Detections out;
    out.stamp = from_seconds(t);
    msg::Detection d;
    d.position = camera.to_camera(Eigen::Vector3d(6.0, 0.5, 3.5));
    out.items.push_back(d);
    ctx.publish(kDetections, std::move(out));
    if (++next_ == 91) ctx.end_of_stream();
  }

 private:
  int next_ = 0;
};

// The last frame's tracks and every frame's target, into the report under the probe's id.
class TracksProbe final : public Node {
 public:
  static constexpr Input<msg::Tracks> kIn{"tracks"};
  static NodeSpec spec() { return NodeSpec("tracks_probe", "Records tracks into the report").input(kIn, "tracks"); }
  explicit TracksProbe(NodeInit&) {}
  void process(Context& ctx) override {
    last_ = ctx.get(kIn);
    targets_.push_back(last_->selected_id ? static_cast<std::int64_t>(*last_->selected_id) : -1);
  }
  void finish(Context& ctx) override {
    nlohmann::json tracks = nlohmann::json::array();
    if (last_)
      for (const auto& t : last_->items)
        tracks.push_back({{"id", t.id},
                          {"age", t.age},
                          {"hits", t.hits},
                          {"state", std::vector<double>(t.state.data(), t.state.data() + t.state.size())}});
    ctx.set_report_section(ctx.id(), ReportSection().quantity("tracks", tracks).quantity("targets", targets_));
  }

 private:
  std::shared_ptr<const msg::Tracks> last_;
  std::vector<std::int64_t> targets_;
};

PluginHost& host() {
  static PluginHost* h = [] {
    auto* p = &kestrel::testing::built_plugins();
    detail::register_node<DetectionReplay>(p->registry());
    detail::register_node<TracksProbe>(p->registry());
    detail::register_node<PitchingCamera>(p->registry());
    return p;
  }();
  return *h;
}

std::string stamps(int frames, double start = 0.0) {
  std::string s = "[";
  for (int k = 0; k < frames; ++k) s += (k ? ", " : "") + std::to_string(start + k / 30.0);
  return s + "]";
}

// Two targets 2 m apart: A at (-1, 0, 5) moving +0.6 m/s in x, B at (1, 2, 7) moving -0.3 m/s in x
// and +0.1 m/s in y.
std::string graph(const std::string& tracker_type, const std::string& tracker_params,
                  const std::string& frame_stamps = stamps(90)) {
  return "kestrel: 1\nname: tracker_node_test\nexecutor: lockstep\nseed: 7\n"
         "nodes:\n"
         "  - id: replay\n    type: detection_replay\n"
         "    params: {stamps_s: " +
         frame_stamps +
         ", starts_m: [-1, 0, 5, 1, 2, 7], velocities_m_s: [0.6, 0, 0, -0.3, 0.1, 0]}\n"
         "  - id: tracker\n    type: " +
         tracker_type + "\n    params: " + tracker_params +
         "\n"
         "  - {id: probe, type: tracks_probe}\n"
         "connections:\n"
         "  - {from: replay.detections, to: tracker.detections, policy: fifo 256}\n"
         "  - {from: tracker.tracks, to: probe.tracks, policy: fifo 256}\n";
}

RunResult run(const std::string& yaml, const std::vector<std::string>& overrides = {}) {
  auto built = build_graph(GraphSource::from_string(yaml, "tracker_node_test.yaml"), host().registry(), overrides);
  EXPECT_TRUE(built.graph) << built.diagnostics.str();
  if (!built.graph) return {};
  return run_graph(*built.graph, host().registry());
}

Eigen::Vector3d position(const nlohmann::json& track) {
  const auto s = track.at("state").get<std::vector<double>>();
  return {s[0], s[1], s[2]};
}
Eigen::Vector3d velocity(const nlohmann::json& track) {
  const auto s = track.at("state").get<std::vector<double>>();
  return {s[3], s[4], s[5]};
}

}  // namespace

// Both filters, named in YAML, on targets whose paths are known: two tracks, born in the first
// frame in the detections' order, each on its target, the older one the target.
TEST(TrackerNode, FollowsTwoTargetsWithEitherFilter) {
  const double t = 89 / 30.0;
  const Eigen::Vector3d a(-1 + 0.6 * t, 0, 5), b(1 - 0.3 * t, 2 + 0.1 * t, 7);
  std::vector<nlohmann::json> states;
  for (const std::string filter : {"{type: kalman, r: 0.05}", "{type: particle, r: 0.05}"}) {
    SCOPED_TRACE(filter);
    const auto r = run(graph("tracker", "{filter: " + filter + "}"));
    ASSERT_EQ(r.outcome, RunOutcome::completed) << (r.errors.empty() ? "" : r.errors.front());
    const auto& probe = r.report.at("probe");
    const auto& tracks = probe.at("tracks");
    ASSERT_EQ(tracks.size(), 2u);
    EXPECT_EQ(tracks[0].at("id"), 1);
    EXPECT_EQ(tracks[1].at("id"), 2);
    EXPECT_EQ(tracks[0].at("hits"), 90);
    EXPECT_LT((position(tracks[0]) - a).norm(), 0.05);
    EXPECT_LT((position(tracks[1]) - b).norm(), 0.05);
    EXPECT_LT((velocity(tracks[0]) - Eigen::Vector3d(0.6, 0, 0)).norm(), 0.15);
    EXPECT_LT((velocity(tracks[1]) - Eigen::Vector3d(-0.3, 0.1, 0)).norm(), 0.15);
    EXPECT_EQ(probe.at("targets"), std::vector<std::int64_t>(90, 1));
    const auto& counts = r.report.at("tracker");
    EXPECT_EQ(counts.at("frames"), 90);
    EXPECT_EQ(counts.at("tracks_started"), 2);
    EXPECT_EQ(counts.at("empty_frames"), 0);
    states.push_back(tracks[0].at("state"));
  }
  EXPECT_NE(states[0], states[1]);  // two filters, not one filter twice
}

// The selector named in YAML (and reached by --set) chooses the target. Both tracks are born in
// the first frame, so the longest-living rule ties and takes track 1 (the first detection's);
// `nearest` takes A, 5 m away, over B, 7.3 m away, whichever track A is.
TEST(TrackerNode, TheSelectorIsAComponentOfTheYaml) {
  const auto yaml = graph("tracker", "{selector: longest_living}", stamps(10));
  auto targets = [&](const std::vector<std::string>& overrides) {
    const auto r = run(yaml, overrides);
    return r.report.at("probe").at("targets").get<std::vector<std::int64_t>>();
  };
  EXPECT_EQ(targets({}), std::vector<std::int64_t>(10, 1));
  EXPECT_EQ(targets({"tracker.selector=nearest"}), std::vector<std::int64_t>(10, 1));
  // Swap the targets' order: B's detection comes first, so B is track 1; nearest still picks A.
  const auto swapped =
      "kestrel: 1\nname: swapped\nexecutor: lockstep\nnodes:\n"
      "  - id: replay\n    type: detection_replay\n"
      "    params: {stamps_s: " +
      stamps(10) +
      ", starts_m: [1, 2, 7, -1, 0, 5], velocities_m_s: [-0.3, 0.1, 0, 0.6, 0, 0]}\n"
      "  - {id: tracker, type: tracker}\n  - {id: probe, type: tracks_probe}\n"
      "connections:\n  - {from: replay.detections, to: tracker.detections, policy: fifo 64}\n"
      "  - {from: tracker.tracks, to: probe.tracks, policy: fifo 64}\n";
  const auto oldest = run(swapped);
  EXPECT_EQ(oldest.report.at("probe").at("targets"), std::vector<std::int64_t>(10, 1));
  const auto nearest = run(swapped, {"tracker.selector=nearest"});
  EXPECT_EQ(nearest.report.at("probe").at("targets"), std::vector<std::int64_t>(10, 2));
}

// A frame stamped before the previous one is an error that names the node, not a crash.
TEST(TrackerNode, DetectionsGoingBackInTimeFailTheRunNamingTheNode) {
  const auto r = run(graph("tracker", "{}", "[0.0, 0.0333, 0.0667, 0.05, 0.1]"));
  EXPECT_EQ(r.outcome, RunOutcome::failed);
  ASSERT_FALSE(r.errors.empty());
  EXPECT_THAT(r.errors.front(), ::testing::HasSubstr("node 'tracker' (tracker)"));
  EXPECT_THAT(r.errors.front(), ::testing::HasSubstr("detections went back in time"));
  EXPECT_THAT(r.errors.front(), ::testing::HasSubstr("0.050000 s came after one at 0.066700 s"));
}

// A component's own parameters are reached by --set node.component.param.
TEST(TrackerNode, OverridesReachIntoComponents) {
  const auto yaml =
      graph("tracker", "{filter: {type: kalman, r: 1.0}, initiator: {type: consecutive_hits}}", stamps(20));
  const auto base = run(yaml);
  const auto sharper = run(yaml, {"tracker.filter.r=0.01"});
  EXPECT_NE(base.report.at("probe").at("tracks")[0].at("state"),
            sharper.report.at("probe").at("tracks")[0].at("state"));
  // confirm_hits 25 > 20 frames: nothing is ever published.
  const auto unconfirmed = run(yaml, {"tracker.initiator.confirm_hits=25"});
  EXPECT_TRUE(unconfirmed.report.at("probe").at("tracks").empty());
  EXPECT_EQ(unconfirmed.report.at("tracker").at("tracks_confirmed"), 0);
  // An unknown component names the known ones.
  auto bad = build_graph(GraphSource::from_string(yaml, "t.yaml"), host().registry(), {"tracker.filter=ukf"});
  EXPECT_FALSE(bad.graph);
  EXPECT_THAT(bad.diagnostics.str(), ::testing::HasSubstr("unknown filter 'ukf'"));
  EXPECT_THAT(bad.diagnostics.str(), ::testing::HasSubstr("imm, kalman, particle"));
}

// A camera that pitches moves a still target across its frame: tracked there, the track learns the
// camera's motion as the target's. Given the hunter's states (`pose`), the tracker keeps the track in
// the world, where the target is still, and publishes it in the camera frame of each frame.
TEST(TrackerNode, GivenTheCamerasPoseATargetStaysStillWhileTheCameraPitches) {
  const auto yaml = [](bool with_pose) {
    return std::string(
               "kestrel: 1\nname: pitching\nexecutor: lockstep\nnodes:\n"
               "  - {id: camera, type: pitching_camera}\n"
               "  - {id: tracker, type: tracker, params: {filter: {type: kalman, q: 10.0, r: 0.05, p: 1.0}}}\n"
               "  - {id: probe, type: tracks_probe}\n"
               "connections:\n"
               "  - {from: camera.detections, to: tracker.detections, policy: fifo 256}\n"
               "  - {from: tracker.tracks, to: probe.tracks, policy: fifo 256}\n") +
           (with_pose ? "  - {from: camera.pose, to: tracker.pose, policy: fifo 256}\n" : "");
  };
  // The last frame, at 3 s, where the camera pitches fastest (1.5 Hz: 4.5 periods), and where it
  // sees the target then.
  const msg::VehicleState last = PitchingCamera::state(3.0);
  const Eigen::Vector3d seen = geometry::camera_on_body(last.position, last.orientation, Eigen::Vector3d(0.1, 0.0, 0.0))
                                   .to_camera(Eigen::Vector3d(6.0, 0.5, 3.5));

  const auto world = run(yaml(true));
  ASSERT_EQ(world.outcome, RunOutcome::completed) << (world.errors.empty() ? "" : world.errors.front());
  EXPECT_EQ(world.report.at("tracker").at("tracks_started"), 1);
  const auto& kept = world.report.at("probe").at("tracks");
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_EQ(kept[0].at("hits"), 91);
  EXPECT_LT((position(kept[0]) - seen).norm(), 0.05);  // published in the camera frame
  EXPECT_LT(velocity(kept[0]).norm(), 0.1);            // the target's own motion: none

  // In the camera frame the same target moves at the pitch rate times its range (17 m/s at the peak).
  const auto camera = run(yaml(false));
  ASSERT_EQ(camera.outcome, RunOutcome::completed) << (camera.errors.empty() ? "" : camera.errors.front());
  const auto& moving = camera.report.at("probe").at("tracks");
  ASSERT_FALSE(moving.empty());
  EXPECT_GT(velocity(moving.back()).norm(), 1.5);

  // With the pose connected but track_in_world off, the tracks are the camera frame's, as unconnected.
  const auto off = run(yaml(true), {"tracker.track_in_world=false"});
  ASSERT_EQ(off.outcome, RunOutcome::completed) << (off.errors.empty() ? "" : off.errors.front());
  const auto& unmoved = off.report.at("probe").at("tracks");
  ASSERT_EQ(unmoved.size(), moving.size());
  EXPECT_EQ(off.report.at("tracker").at("tracks_started"), camera.report.at("tracker").at("tracks_started"));
  EXPECT_EQ(position(unmoved.back()), position(moving.back()));
  EXPECT_EQ(velocity(unmoved.back()), velocity(moving.back()));
}
