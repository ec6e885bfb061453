// The example from the README's plugin tutorial: a source, a transform and a sink of a framework
// message, each with its parameters declared once in a config struct.
#include <fmt/format.h>

#include <cmath>
#include <kestrel/messages/detections.hpp>
#include <kestrel/plugin.hpp>

namespace hello {

// Every parameter is a field; its initial value is the parameter's default.
struct GreeterConfig {
  enum class Axis { x, y };
  double rate_hz = 10.0;
  double step_m = 0.5;
  double start_m = 0.0;
  double end_m = 10.0;
  Axis axis = Axis::x;
};

// Publishes one detection per tick, 5 m ahead, walking from start_m to end_m and starting over.
class Greeter final : public kestrel::Node {
 public:
  static constexpr kestrel::Output<kestrel::msg::Detections> kOut{"detections"};

  static kestrel::NodeSpec spec() {
    using C = GreeterConfig;
    kestrel::ConfigSpec<C> c;
    c.param("rate_hz", &C::rate_hz).with_unit("Hz").range(0.1, 1000.0).describe("ticks per second");
    c.param("step_m", &C::step_m).with_unit("m").at_least(0.0).describe("how far the detection moves per tick");
    c.param("start_m", &C::start_m).with_unit("m").describe("where the walk starts");
    c.param("end_m", &C::end_m).with_unit("m").describe("where it starts over");
    c.choice("axis", &C::axis, {{"x", C::Axis::x}, {"y", C::Axis::y}}).describe("camera axis walked along");
    // A condition over several parameters: `kestrel validate` reports it with file:line:col.
    c.rule("start_m < end_m", {"start_m", "end_m"}, [](const C& k) { return k.start_m < k.end_m; });
    return kestrel::NodeSpec("greeter", "Says hello, then publishes a detection walking along an axis")
        .details("A source: it ticks at rate_hz and stamps each message with the time of its tick.")
        .output(kOut, "one detection per tick")
        .config(std::move(c));
  }

  explicit Greeter(kestrel::NodeInit& init) : cfg_(init.config<GreeterConfig>()) {
    init.set_rate(cfg_.rate_hz);  // tick() at this rate: a source
    init.log().info("hello from {}", init.id());
  }

  void tick(kestrel::Context& ctx) override {
    const double along = cfg_.start_m + std::fmod(cfg_.step_m * ticks_++, cfg_.end_m - cfg_.start_m);
    kestrel::msg::Detection d;
    d.position =
        cfg_.axis == GreeterConfig::Axis::x ? Eigen::Vector3d(along, 0.0, 5.0) : Eigen::Vector3d(0.0, along, 5.0);
    d.point_count = 1;
    kestrel::msg::Detections out;
    out.stamp = ctx.now();  // a source's data is captured now
    out.items.push_back(d);
    ctx.publish(kOut, std::move(out));  // travels as shared_ptr<const Detections>
  }

 private:
  GreeterConfig cfg_;
  int ticks_ = 0;
};
KESTREL_REGISTER_NODE(Greeter)

struct ShiftConfig {
  Eigen::Vector3d offset_m{0.0, 0.0, 0.0};
};

// Moves every detection by a fixed offset: a transform.
class Shift final : public kestrel::Node {
 public:
  static constexpr kestrel::Input<kestrel::msg::Detections> kIn{"in"};
  static constexpr kestrel::Output<kestrel::msg::Detections> kOut{"out"};

  static kestrel::NodeSpec spec() {
    kestrel::ConfigSpec<ShiftConfig> c;
    c.param("offset_m", &ShiftConfig::offset_m).with_unit("m").describe("added to every position (camera frame)");
    return kestrel::NodeSpec("shift", "Moves detections by a fixed offset")
        .input(kIn, "detections")
        .output(kOut, "the same detections, moved")
        .config(std::move(c));
  }

  explicit Shift(kestrel::NodeInit& init) : cfg_(init.config<ShiftConfig>()) {}

  void process(kestrel::Context& ctx) override {
    kestrel::msg::Detections out = *ctx.get(kIn);  // a copy: published messages are immutable
    for (auto& d : out.items) d.position += cfg_.offset_m;
    // out.stamp stays the input's: the capture time travels with the data, whenever it is processed.
    ctx.publish(kOut, std::move(out));
  }

 private:
  ShiftConfig cfg_;
};
KESTREL_REGISTER_NODE(Shift)

struct CounterConfig {
  std::string section;
};

// Counts detections into the run report, and lists them in a CSV file beside it.
class DetectionCounter final : public kestrel::Node {
 public:
  static constexpr kestrel::Input<kestrel::msg::Detections> kIn{"detections"};

  static kestrel::NodeSpec spec() {
    kestrel::ConfigSpec<CounterConfig> c;
    c.required("section", &CounterConfig::section).describe("report.json key of the count");
    return kestrel::NodeSpec("detection_counter", "Counts detections into the report")
        .input(kIn, "detections to count")
        .config(std::move(c));
  }

  explicit DetectionCounter(kestrel::NodeInit& init) : cfg_(init.config<CounterConfig>()) {}

  void process(kestrel::Context& ctx) override {
    const auto in = ctx.get(kIn);
    for (const auto& d : in->items)
      rows_ += fmt::format("{:.3f},{:.3f},{:.3f},{:.3f}\n", kestrel::to_seconds(in->stamp), d.position.x(),
                           d.position.y(), d.position.z());
    seen_ += in->items.size();
  }

  void finish(kestrel::Context& ctx) override {
    // Each value says its unit and which way is better; `kestrel sweep` and `ab` judge runs by it.
    ctx.set_report_section(cfg_.section,
                           kestrel::ReportSection().metric("detections_seen", seen_, "", kestrel::Better::higher));
    // The runtime writes the file into the report folder, checks the write and lists it.
    if (ctx.keeps_artifacts()) ctx.add_artifact("detections.csv", "t_s,x_m,y_m,z_m\n" + rows_, "every detection");
  }

 private:
  CounterConfig cfg_;
  std::size_t seen_ = 0;
  std::string rows_;
};
KESTREL_REGISTER_NODE(DetectionCounter)

}  // namespace hello
