// The `detection_dropout` node: a temporary occlusion. It passes detections through, except
// during blackouts of `frames` frames every `period_s` seconds, when it passes none.
#include <kestrel/messages/detections.hpp>
#include <kestrel/plugin.hpp>

#include "blackout_schedule.hpp"

namespace kestrel::scenario {

class DetectionDropout final : public Node {
 public:
  static constexpr Input<msg::Detections> kIn{"detections"};
  static constexpr Output<msg::Detections> kOut{"detections"};

  struct Config {
    int frames = 10;
    double first_s = 3.0;
    double period_s = 6.0;
  };

  static NodeSpec spec() {
    ConfigSpec<Config> c;
    c.param("frames", &Config::frames).range(0, 100000).describe("frames per blackout");
    c.param("first_s", &Config::first_s).range(0.0, 1e6).with_unit("s").describe("capture time of the first blackout");
    c.param("period_s", &Config::period_s).range(0.001, 1e6).with_unit("s").describe("time between blackout starts");
    return NodeSpec("detection_dropout", "Temporary occlusion: drops every detection for N frames at a time")
        .details(
            "Frames are counted as they arrive. From first_s on, every period_s a blackout of `frames` frames "
            "publishes an empty detection list (with the frame's stamp), as if the intruder were hidden.")
        .input(kIn, "detections")
        .output(kOut, "detections, empty during blackouts")
        .config(std::move(c));
  }

  explicit DetectionDropout(NodeInit& init) : DetectionDropout(init.config<Config>()) {}
  explicit DetectionDropout(const Config& cfg) : schedule_(cfg.frames, cfg.first_s, cfg.period_s) {}

  void process(Context& ctx) override {
    const auto in = ctx.get(kIn);
    if (schedule_.hide(to_seconds(in->stamp))) {
      msg::Detections empty;
      empty.stamp = in->stamp;
      empty.frame = in->frame;
      ctx.publish(kOut, std::move(empty));
      return;
    }
    ctx.publish(kOut, in);
  }

 private:
  BlackoutSchedule schedule_;
};
KESTREL_REGISTER_NODE(DetectionDropout)

}  // namespace kestrel::scenario
