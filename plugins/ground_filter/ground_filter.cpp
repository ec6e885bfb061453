// The `ground_filter` node: takes the ground out of a stereo cloud, using the pose of the vehicle
// that carries the camera (ground_removal.hpp). Between the voxel grid and the clusters, it keeps
// the far ground that a tilting hunter sees from clustering into targets at any range.
#include <fmt/format.h>

#include <kestrel/geometry/frames.hpp>
#include <kestrel/messages/point_cloud.hpp>
#include <kestrel/messages/vehicle_state.hpp>
#include <kestrel/plugin.hpp>
#include <kestrel/vehicle/state_history.hpp>

#include "ground_removal.hpp"

namespace kestrel::ground {

struct GroundFilterConfig {
  GroundOptions ground;
  Eigen::Vector3d camera_offset_m{0.1, 0.0, 0.0};
};

class GroundFilterNode final : public Node {
 public:
  static constexpr Input<msg::PointCloud> kCloud{"cloud"};
  static constexpr Input<msg::VehicleState> kPose{"pose"};
  static constexpr Output<msg::PointCloud> kFiltered{"filtered"};

  static NodeSpec spec() {
    using C = GroundFilterConfig;
    ConfigSpec<C> c;
    c.param("margin_px", &C::ground, &GroundOptions::margin_px)
        .with_unit("px")
        .range(0.0, 64.0)
        .describe(
            "a point nearer than the ground along its own ray by less than this much disparity is ground (so is "
            "everything beneath the plane); stereo's noise is a fraction of a pixel at every range");
    c.param("ground_z_m", &C::ground, &GroundOptions::ground_z_m)
        .with_unit("m")
        .range(-1000.0, 1000.0)
        .describe("height of the ground plane (world z)");
    c.param("camera_offset_m", &C::camera_offset_m)
        .with_unit("m")
        .range(-10.0, 10.0)
        .describe("the camera's position in the vehicle's body frame (as the camera node has it)");
    return NodeSpec("ground_filter", "Takes the ground out of a stereo cloud, by the camera carrier's pose")
        .details(
            "For each point, the ray from the camera through it is followed to the ground plane; the point is ground "
            "when its disparity exceeds the ground's on that ray by less than margin_px. Far away, where rays graze "
            "the ground and a fraction of a pixel moves a ground point metres along its ray (and so up off the "
            "plane), this holds where a height threshold does not. Needs a stereo cloud (focal_baseline_px_m). "
            "The pose is the carrier's at the cloud's capture time, interpolated between the states received (a "
            "cloud comes out of the depth stage tens of milliseconds after its frame was taken, the vehicle turning "
            "on meanwhile). Without a pose (before the first, or with the input unconnected, as in the still "
            "camera's graphs) the cloud passes whole, and such clouds are counted.")
        .input(kCloud, "camera-frame stereo points")
        .input(kPose,
               "every state of the vehicle carrying the camera, kept 2 s (unconnected: a camera that does not fly)",
               {.optional = true})
        .output(kFiltered, "the points that are not ground")
        .config(std::move(c));
  }

  explicit GroundFilterNode(NodeInit& init) : cfg_(init.config<GroundFilterConfig>()) {}

  void process(Context& ctx) override {
    if (ctx.triggered_by(kPose)) {
      poses_.add(*ctx.get(kPose));
      return;
    }
    const auto in = ctx.get(kCloud);
    if (!in->points) throw Error("point cloud message without points");
    const auto pose = poses_.at(in->stamp);
    msg::PointCloud out = *in;
    if (pose) {
      if (!(in->focal_baseline_px_m > 0.0))
        throw Error(
            "the cloud is not from stereo (focal_baseline_px_m 0): connect stereo_depth's cloud, through "
            "filters that keep it");
      const auto camera = geometry::camera_on_body(pose->position, pose->orientation, cfg_.camera_offset_m);
      out.points = remove_ground(*in->points, camera, in->focal_baseline_px_m, cfg_.ground);
    } else {
      ++without_pose_;
    }
    points_ += in->points->size();
    removed_ += in->points->size() - out.points->size();
    ++clouds_;
    ctx.publish(kFiltered, std::move(out));
  }

  void finish(Context& ctx) override {
    const std::string id = ctx.id();
    ctx.set_report_section(
        id, ReportSection()
                .quantity("clouds", clouds_)
                .quantity("points", points_)
                .quantity("removed", removed_)
                .quantity("clouds_without_pose", without_pose_)
                .markdown(fmt::format("{} of {} points taken out as ground ({:.2f} px margin); {} of {} clouds passed "
                                      "whole, without a pose.\n",
                                      removed_, points_, cfg_.ground.margin_px, without_pose_, clouds_)));
  }

 private:
  GroundFilterConfig cfg_;
  vehicle::StateHistory poses_;
  std::uint64_t clouds_ = 0, points_ = 0, removed_ = 0, without_pose_ = 0;
};
KESTREL_REGISTER_NODE(GroundFilterNode)

}  // namespace kestrel::ground
