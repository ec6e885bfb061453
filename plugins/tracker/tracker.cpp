// The `tracker` node: the paper's multi-target tracker (section 2.3), composed from components
// that YAML names and configures one by one, Stone Soup style:
//
//   - id: tracker
//     type: tracker
//     params:
//       filter: {type: kalman, r: 1.0}             # or particle (plugins/particle_filter)
//       associator: {type: hungarian, gate_m: 1.0}  # or greedy (plugins/associators)
//       initiator: {type: consecutive_hits, confirm_hits: 1}
//       deleter: {type: consecutive_misses, max_misses: 10}
//       selector: longest_living                    # or most_hits, nearest, most_confident
//
// Every number belongs to the component that uses it; the node only names the components.
// This plugin also provides the components that need no other library.
#include <kestrel/geometry/frames.hpp>
#include <kestrel/messages/vehicle_state.hpp>
#include <kestrel/plugin.hpp>
#include <kestrel/tracking/deleter.hpp>
#include <kestrel/tracking/imm_filter.hpp>
#include <kestrel/tracking/initiator.hpp>
#include <kestrel/tracking/kalman_filter.hpp>
#include <kestrel/tracking/selector.hpp>
#include <kestrel/tracking/tracker_node.hpp>
#include <kestrel/vehicle/state_history.hpp>

#include "tracks_in_world.hpp"

namespace kestrel::tracking {

struct TrackerConfig {
  ComponentConfig filter;
  ComponentConfig associator;
  ComponentConfig initiator;
  ComponentConfig deleter;
  ComponentConfig selector;
  Eigen::Vector3d camera_offset_m{0.1, 0.0, 0.0};
  bool track_in_world = true;
};

class Tracker final : public TrackerNode {
 public:
  static NodeSpec spec() {
    ConfigSpec<TrackerConfig> c;
    c.component("filter", &TrackerConfig::filter, "filter", "kalman")
        .describe(
            "per-track estimator with its noise parameters: kalman (the paper's constant-acceleration Kalman "
            "filter: q, r, p) or particle (the same model as MRPT particle filters)");
    declare_associator(c, &TrackerConfig::associator);
    c.component("initiator", &TrackerConfig::initiator, "initiator", "consecutive_hits")
        .describe("which detections start tracks and when a track is confirmed: consecutive_hits (confirm_hits)");
    c.component("deleter", &TrackerConfig::deleter, "deleter", "consecutive_misses")
        .describe("when a confirmed track ends: consecutive_misses (max_misses)");
    c.component("selector", &TrackerConfig::selector, "selector", "longest_living")
        .describe(
            "which confirmed track is the target: longest_living (the paper's), most_hits, nearest or "
            "most_confident; a tie goes to the oldest track");
    c.param("camera_offset_m", &TrackerConfig::camera_offset_m)
        .with_unit("m")
        .range(-10.0, 10.0)
        .describe("with pose connected: the camera's position in the body frame of the vehicle carrying it");
    c.param("track_in_world", &TrackerConfig::track_in_world)
        .describe(
            "with pose connected: keep the tracks in the world (true) or in the detections' frame, as if pose were "
            "unconnected (false: the paper's tracker, to compare the two on one graph with --set)");
    return with_ports(NodeSpec("tracker", "Multi-target tracker made of swappable components (paper, 2.3)"))
        .details(
            "Each frame: every track's filter predicts to the frame's time; the associator pairs tracks with "
            "detections within its gate; paired tracks are updated; the initiator confirms or drops tentative "
            "tracks and the deleter ends confirmed ones; each detection no track claimed starts a tentative "
            "track; the selector chooses the target among the confirmed tracks, which alone are published. The "
            "defaults are the paper's tracker: Kalman filter with q = r = p = 1, Hungarian association within "
            "1.0 m, a track published at birth, deleted after 10 misses, the longest-living track as the target. "
            "With `pose` connected (the vehicle carrying the camera), the tracks are kept in the world: each "
            "frame's detections are taken there with the camera's pose at the capture, and the tracks are "
            "published in that frame's camera frame again; a camera that turns then no longer moves its targets' "
            "tracks (the selector `nearest` then measures from the world's origin). Frames before the first pose "
            "are tracked in the camera frame.")
        .input(kPose,
               "every state of the vehicle carrying the camera (kept 2 s); unconnected: the tracks are kept "
               "in the detections' frame (the paper's)",
               {.optional = true})
        .config(std::move(c));
  }

  static constexpr Input<msg::VehicleState> kPose{"pose"};

  explicit Tracker(NodeInit& init)
      : TrackerNode(TrackerParts{init.make_component<Filter>("filter"), init.make_component<Associator>("associator"),
                                 init.make_component<Initiator>("initiator"), init.make_component<Deleter>("deleter"),
                                 init.make_component<Selector>("selector")}),
        camera_offset_m_(init.config<TrackerConfig>().camera_offset_m),
        track_in_world_(init.config<TrackerConfig>().track_in_world) {}

  void process(Context& ctx) override {
    if (ctx.triggered_by(kPose)) {
      if (track_in_world_) poses_.add(*ctx.get(kPose));
      return;
    }
    const auto pose = poses_.at(ctx.get(kDetections)->stamp);
    if (!pose) {  // pose unconnected, or none yet: the detections' own frame
      TrackerNode::process(ctx);
      return;
    }
    const auto detections = ctx.get(kDetections);
    const geometry::CameraPose camera = geometry::camera_on_body(pose->position, pose->orientation, camera_offset_m_);
    std::vector<Eigen::Vector3d> in_world;
    in_world.reserve(detections->items.size());
    for (const auto& d : detections->items) in_world.push_back(camera.to_world(d.position));
    msg::Tracks tracks = step(detections->stamp, in_world);
    for (msg::Track& t : tracks.items) t = track_in_camera(std::move(t), camera);
    tracks.frame = detections->frame;
    ctx.publish(kTracks, std::move(tracks));
  }

 private:
  Eigen::Vector3d camera_offset_m_;
  bool track_in_world_;
  vehicle::StateHistory poses_;
};
KESTREL_REGISTER_NODE(Tracker)

}  // namespace kestrel::tracking

KESTREL_REGISTER_COMPONENT(kestrel::tracking::Filter, kestrel::tracking::KalmanFilter)
KESTREL_REGISTER_COMPONENT(kestrel::tracking::Filter, kestrel::tracking::ImmFilter)
KESTREL_REGISTER_COMPONENT(kestrel::tracking::Initiator, kestrel::tracking::ConsecutiveHitsInitiator)
KESTREL_REGISTER_COMPONENT(kestrel::tracking::Deleter, kestrel::tracking::ConsecutiveMissesDeleter)
KESTREL_REGISTER_COMPONENT(kestrel::tracking::Selector, kestrel::tracking::LongestLivingSelector)
KESTREL_REGISTER_COMPONENT(kestrel::tracking::Selector, kestrel::tracking::MostHitsSelector)
KESTREL_REGISTER_COMPONENT(kestrel::tracking::Selector, kestrel::tracking::NearestSelector)
KESTREL_REGISTER_COMPONENT(kestrel::tracking::Selector, kestrel::tracking::MostConfidentSelector)
