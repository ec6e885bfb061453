// The `height_gate` node: drops detections lower than a height above the ground, using the pose
// of the vehicle that carries the camera. A hunter's camera tilts and sees the ground, and
// stereo noise breaks pieces off it that cluster like small objects; nothing on the ground is a
// flying intruder. Without a pose their height is unknown: they are dropped, and counted.
#include <fmt/format.h>

#include <kestrel/geometry/frames.hpp>
#include <kestrel/messages/detections.hpp>
#include <kestrel/messages/vehicle_state.hpp>
#include <kestrel/plugin.hpp>
#include <kestrel/vehicle/state_history.hpp>

namespace kestrel::gate {

struct HeightGateConfig {
  double min_height_m = 0.5;
  Eigen::Vector3d camera_offset_m{0.1, 0.0, 0.0};
};

class HeightGateNode final : public Node {
 public:
  static constexpr Input<msg::Detections> kDetections{"detections"};
  static constexpr Input<msg::VehicleState> kPose{"pose"};
  static constexpr Output<msg::Detections> kKept{"detections"};

  static NodeSpec spec() {
    using C = HeightGateConfig;
    ConfigSpec<C> c;
    c.param("min_height_m", &C::min_height_m)
        .with_unit("m")
        .range(-1000.0, 1000.0)
        .describe("detections lower than this (world z) are dropped");
    c.param("camera_offset_m", &C::camera_offset_m)
        .with_unit("m")
        .range(-10.0, 10.0)
        .describe("the camera's position in the vehicle's body frame (as the camera node has it)");
    return NodeSpec("height_gate", "Drops detections near the ground, using the camera carrier's pose")
        .details(
            "Each detection's camera-frame position is taken to the world frame with the pose the vehicle carrying "
            "the camera had when the frame was taken (interpolated between the states received, at the "
            "detections' stamp); those below min_height_m are dropped. Keeps the stamp and frame. Without a pose "
            "yet, every detection is dropped (their height is unknown).")
        .input(kDetections, "detections in the camera frame")
        .input(kPose, "every state of the vehicle carrying the camera (kept 2 s)")
        .output(kKept, "the detections above min_height_m")
        .config(std::move(c));
  }

  explicit HeightGateNode(NodeInit& init) : cfg_(init.config<HeightGateConfig>()) {}

  void process(Context& ctx) override {
    if (ctx.triggered_by(kPose)) {
      poses_.add(*ctx.get(kPose));
      return;
    }
    const auto in = ctx.get(kDetections);
    const auto pose = poses_.at(in->stamp);
    msg::Detections out;
    out.stamp = in->stamp;
    out.frame = in->frame;
    if (pose) {
      const auto camera = geometry::camera_on_body(pose->position, pose->orientation, cfg_.camera_offset_m);
      for (const auto& d : in->items)
        if (camera.to_world(d.position).z() >= cfg_.min_height_m) out.items.push_back(d);
    }
    seen_ += in->items.size();
    dropped_ += in->items.size() - out.items.size();
    ctx.publish(kKept, std::move(out));
  }

  void finish(Context& ctx) override {
    const std::string id = ctx.id();
    ctx.set_report_section(id, ReportSection()
                                   .quantity("detections", seen_)
                                   .quantity("dropped", dropped_)
                                   .markdown(fmt::format("{} of {} detections dropped as lower than {:.2f} m.\n",
                                                         dropped_, seen_, cfg_.min_height_m)));
  }

 private:
  HeightGateConfig cfg_;
  vehicle::StateHistory poses_;
  std::uint64_t seen_ = 0, dropped_ = 0;
};
KESTREL_REGISTER_NODE(HeightGateNode)

}  // namespace kestrel::gate
