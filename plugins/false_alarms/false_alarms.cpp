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

  struct Config {
    double rate_per_frame = 0.5;
    FalseAlarmBox box;
  };

  static NodeSpec spec() {
    ConfigSpec<Config> c;
    c.param("rate_per_frame", &Config::rate_per_frame).range(0.0, 1000.0).describe("mean false detections per frame");
    c.param("box_min_m", &Config::box, &FalseAlarmBox::min)
        .with_unit("m")
        .describe("box corner, camera frame (x right, y down, z ahead)");
    c.param("box_max_m", &Config::box, &FalseAlarmBox::max).with_unit("m").describe("opposite box corner");
    c.rule("box_min_m <= box_max_m on every axis", {"box_min_m", "box_max_m"},
           [](const Config& k) { return (k.box.max - k.box.min).minCoeff() >= 0.0; });
    return NodeSpec("false_alarms", "Clutter: adds Poisson false detections, uniform in a box, to every frame")
        .details(
            "Each frame gets a Poisson number of false detections with mean rate_per_frame, uniformly "
            "spread over the camera-frame box [box_min_m, box_max_m] (Stone Soup's clutter model). They carry "
            "point_count 0, so they can be told apart in logs; trackers see them as any other detection. "
            "Drawn with the node's seeded generator: lockstep runs reproduce.")
        .input(kIn, "detections")
        .output(kOut, "the same detections followed by the false ones")
        .config(std::move(c));
  }

  explicit FalseAlarms(NodeInit& init) : FalseAlarms(init.config<Config>()) {}
  explicit FalseAlarms(const Config& cfg) : model_(cfg.rate_per_frame, cfg.box) {}

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
