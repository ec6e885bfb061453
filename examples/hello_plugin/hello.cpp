// The example from the README's plugin tutorial: a source and a sink using a framework message.
#include <kestrel/messages/detections.hpp>
#include <kestrel/plugin.hpp>

namespace hello {

// Publishes one detection per tick, walking along the camera's x axis.
class Greeter final : public kestrel::Node {
 public:
  static constexpr kestrel::Output<kestrel::msg::Detections> kOut{"detections"};

  static kestrel::NodeSpec spec() {
    return kestrel::NodeSpec("greeter", "Says hello, then publishes a detection walking along x")
        .output(kOut, "one detection per tick")
        .param(kestrel::param("rate_hz", 10.0).with_unit("Hz").range(0.1, 1000.0).describe("ticks per second"))
        .param(kestrel::param("step_m", 0.5).with_unit("m").describe("how far the detection moves per tick"));
  }

  explicit Greeter(kestrel::NodeInit& init) : step_(init.param<double>("step_m")) {
    init.set_rate(init.param<double>("rate_hz"));
    init.log().info("hello from {}", init.id());
  }

  void tick(kestrel::Context& ctx) override {
    kestrel::msg::Detections out;
    out.stamp = ctx.now();
    out.items.push_back(
        {Eigen::Vector3d(step_ * static_cast<double>(ticks_++), 0.0, 5.0), Eigen::Vector3d::Zero(), 1, 1.0});
    ctx.publish(kOut, std::move(out));
  }

 private:
  double step_;
  int ticks_ = 0;
};
KESTREL_REGISTER_NODE(Greeter)

// Counts detections and adds the total to the run report.
class DetectionCounter final : public kestrel::Node {
 public:
  static constexpr kestrel::Input<kestrel::msg::Detections> kIn{"detections"};

  static kestrel::NodeSpec spec() {
    return kestrel::NodeSpec("detection_counter", "Counts detections into the report")
        .input(kIn, "detections to count");
  }
  explicit DetectionCounter(kestrel::NodeInit&) {}

  void process(kestrel::Context& ctx) override { seen_ += ctx.get(kIn)->items.size(); }
  void finish(kestrel::Context& ctx) override { ctx.set_report_section("hello", {{"detections_seen", seen_}}); }

 private:
  std::size_t seen_ = 0;
};
KESTREL_REGISTER_NODE(DetectionCounter)

}  // namespace hello
