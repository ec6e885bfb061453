// The `false_alarms` node: adds clutter detections to each frame's detections (Poisson count,
// uniform in a box), for measuring how a tracker copes with false alarms.
#include <kestrel/messages/detections.hpp>
#include <kestrel/plugin.hpp>

#include "false_alarm_model.hpp"

namespace kestrel::scenario {

class FalseAlarms final : public Node {
 public:
  static constexpr Input<msg::Detections> kIn{"detections"};
  static constexpr Output<msg::Detections> kOut{"detections"};

  static NodeSpec spec() {
    return NodeSpec("false_alarms", "Clutter: adds Poisson false detections, uniform in a box, to every frame")
        .details(
            "Each frame gets a Poisson number of false detections with mean rate_per_frame, uniformly "
            "spread over the camera-frame box [box_min_m, box_max_m] (Stone Soup's clutter model). They carry "
            "point_count 0, so they can be told apart in logs; trackers see them as any other detection. "
            "Drawn with the node's seeded generator: lockstep runs reproduce.")
        .input(kIn, "detections")
        .output(kOut, "the same detections followed by the false ones")
        .param(param("rate_per_frame", 0.5).range(0.0, 1000.0).describe("mean false detections per frame"))
        .param(param("box_min_m", std::vector<double>{-3.0, -2.0, 2.0})
                   .with_length(3)
                   .with_unit("m")
                   .describe("box corner, camera frame (x right, y down, z ahead)"))
        .param(param("box_max_m", std::vector<double>{3.0, 2.0, 10.0})
                   .with_length(3)
                   .with_unit("m")
                   .describe("opposite box corner"));
  }

  explicit FalseAlarms(NodeInit& init)
      : model_(init.param<double>("rate_per_frame"),
               FalseAlarmBox{init.param<Eigen::Vector3d>("box_min_m"), init.param<Eigen::Vector3d>("box_max_m")}) {}

  void process(Context& ctx) override {
    const auto in = ctx.get(kIn);
    msg::Detections out = *in;
    for (const auto& p : model_.draw(ctx.rng())) {
      msg::Detection d;
      d.position = p;
      d.point_count = 0;
      out.items.push_back(d);
    }
    ctx.publish(kOut, std::move(out));
  }

 private:
  FalseAlarmModel model_;
};
KESTREL_REGISTER_NODE(FalseAlarms)

}  // namespace kestrel::scenario
