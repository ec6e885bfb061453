// Nodes that pass, change, combine or fail on numbers.
#include <array>
#include <kestrel/plugin.hpp>
#include <thread>

#include "test_messages.hpp"

namespace kestrel::test {

class Relay final : public Node {
 public:
  static constexpr Input<Number> kIn{"in"};
  static constexpr Output<Number> kOut{"out"};
  static NodeSpec spec() {
    return NodeSpec("relay", "Republishes each number unchanged (the same shared message)")
        .input(kIn, "numbers")
        .output(kOut, "the same numbers");
  }
  explicit Relay(NodeInit&) {}
  void process(Context& ctx) override { ctx.publish(kOut, ctx.get(kIn)); }
};
KESTREL_REGISTER_NODE(Relay)

class BlobRelay final : public Node {
 public:
  static constexpr Input<Blob> kIn{"in"};
  static constexpr Output<Blob> kOut{"out"};
  static NodeSpec spec() {
    return NodeSpec("blob_relay", "Republishes each blob unchanged (the same shared message)")
        .input(kIn, "blobs")
        .output(kOut, "the same blobs");
  }
  explicit BlobRelay(NodeInit&) {}
  void process(Context& ctx) override { ctx.publish(kOut, ctx.get(kIn)); }
};
KESTREL_REGISTER_NODE(BlobRelay)

struct ScaleConfig {
  enum class Mode { multiply, divide };
  double factor = 2.0;
  Mode mode = Mode::multiply;
  std::vector<double> offsets;
  bool enabled = true;
};

class Scale final : public Node {
 public:
  static constexpr Input<Number> kIn{"in"};
  static constexpr Output<Number> kOut{"out"};
  static NodeSpec spec() {
    using Mode = ScaleConfig::Mode;
    ConfigSpec<ScaleConfig> c;
    c.param("factor", &ScaleConfig::factor).range(-1e6, 1e6).describe("the multiplier");
    c.choice("mode", &ScaleConfig::mode, {{"multiply", Mode::multiply}, {"divide", Mode::divide}})
        .describe("what to do");
    c.param("offsets", &ScaleConfig::offsets).describe("added to the result, one per message, cycling");
    c.param("enabled", &ScaleConfig::enabled).describe("false passes numbers through");
    return NodeSpec("scale", "Multiplies each number by a factor")
        .input(kIn, "numbers")
        .output(kOut, "scaled numbers")
        .config(std::move(c));
  }
  explicit Scale(NodeInit& init) : cfg_(init.config<ScaleConfig>()) {}
  void process(Context& ctx) override {
    Number n = *ctx.get(kIn);
    if (cfg_.enabled) n.value = cfg_.mode == ScaleConfig::Mode::divide ? n.value / cfg_.factor : n.value * cfg_.factor;
    if (!cfg_.offsets.empty()) n.value += cfg_.offsets[static_cast<std::size_t>(n.index) % cfg_.offsets.size()];
    ctx.publish(kOut, n);
  }

 private:
  ScaleConfig cfg_;
};
KESTREL_REGISTER_NODE(Scale)

struct WindowConfig {
  double low = -1.0;
  double high = 1.0;
  std::array<double, 2> fallback{0.0, 0.0};
};

// Passes numbers inside [low, high]; the others become fallback[0] (below) or fallback[1] (above).
class Window final : public Node {
 public:
  static constexpr Input<Number> kIn{"in"};
  static constexpr Output<Number> kOut{"out"};
  static NodeSpec spec() {
    ConfigSpec<WindowConfig> c;
    c.param("low", &WindowConfig::low).describe("lowest value passed");
    c.param("high", &WindowConfig::high).describe("highest value passed");
    c.param("fallback", &WindowConfig::fallback).describe("published instead of a value below / above the window");
    c.rule("low <= high", {"low", "high"}, [](const WindowConfig& k) { return k.low <= k.high; });
    return NodeSpec("window", "Passes numbers inside a window")
        .input(kIn, "numbers")
        .output(kOut, "numbers")
        .config(std::move(c));
  }
  explicit Window(NodeInit& init) : cfg_(init.config<WindowConfig>()) {}
  void process(Context& ctx) override {
    Number n = *ctx.get(kIn);
    if (n.value < cfg_.low) n.value = cfg_.fallback[0];
    if (n.value > cfg_.high) n.value = cfg_.fallback[1];
    ctx.publish(kOut, n);
  }

 private:
  WindowConfig cfg_;
};
KESTREL_REGISTER_NODE(Window)

// a + (latest b): `a` triggers, `b` is read as its newest value.
class Adder final : public Node {
 public:
  static constexpr Input<Number> kA{"a"};
  static constexpr Input<Number> kB{"b"};
  static constexpr Output<Number> kSum{"sum"};
  static NodeSpec spec() {
    return NodeSpec("adder", "Adds the newest b to each a")
        .input(kA, "triggers a sum")
        .input(kB, "read as its latest value (0 before the first)", {.trigger = Trigger::latest, .optional = true})
        .output(kSum, "a + b");
  }
  explicit Adder(NodeInit&) {}
  void process(Context& ctx) override {
    const auto a = ctx.get(kA);
    const auto b = ctx.get(kB);
    ctx.publish(kSum, Number{a->index, a->value + (b ? b->value : 0.0)});
  }
};
KESTREL_REGISTER_NODE(Adder)

class Faulty final : public Node {
 public:
  static constexpr Input<Number> kIn{"in"};
  static constexpr Output<Number> kOut{"out"};
  static NodeSpec spec() {
    return NodeSpec("faulty", "Passes numbers through but throws on chosen ones")
        .input(kIn, "numbers")
        .output(kOut, "numbers that did not fail")
        .param(
            param("fail_every", 0).at_least(0).describe("throw when index % fail_every == fail_every - 1; 0 = never"))
        .param(param("fail_on_start", false).describe("throw from the constructor"));
  }
  explicit Faulty(NodeInit& init) : every_(init.param<std::int64_t>("fail_every")) {
    if (init.param<bool>("fail_on_start")) throw Error("cannot open the imaginary device");
  }
  void process(Context& ctx) override {
    const auto n = ctx.get(kIn);
    if (every_ > 0 && n->index % every_ == every_ - 1) throw Error("bad number " + std::to_string(n->index));
    ctx.publish(kOut, n);
  }

 private:
  std::int64_t every_;
};
KESTREL_REGISTER_NODE(Faulty)

class Slow final : public Node {
 public:
  static constexpr Input<Number> kIn{"in"};
  static constexpr Output<Number> kOut{"out"};
  static NodeSpec spec() {
    return NodeSpec("slow", "Sleeps (wall clock) before passing each number on")
        .input(kIn, "numbers")
        .output(kOut, "the same numbers, late")
        .param(param("delay_ms", 10.0).range(0.0, 10000.0).with_unit("ms").describe("sleep per message"));
  }
  explicit Slow(NodeInit& init) : delay_(init.param<double>("delay_ms")) {}
  void process(Context& ctx) override {
    std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(delay_));
    ctx.publish(kOut, ctx.get(kIn));
  }

 private:
  double delay_;
};
KESTREL_REGISTER_NODE(Slow)

}  // namespace kestrel::test
