// A component kind for the tests: strategies a node builds by name from its parameters.
#include <algorithm>
#include <kestrel/plugin.hpp>

#include "test_messages.hpp"

namespace kestrel::test {

struct Shaper {
  static constexpr std::string_view kKind = "shaper";
  virtual ~Shaper() = default;
  virtual double shape(double value) const = 0;
};

// The older form: a component built from its parameters alone.
class OffsetShaper final : public Shaper {
 public:
  static ComponentSpec spec() {
    return ComponentSpec("offset", "Adds a constant").param(param("amount", 1.0).range(-100, 100).describe("added"));
  }
  explicit OffsetShaper(const Params& p) : amount_(p.get<double>("amount")) {}
  double shape(double v) const override { return v + amount_; }

 private:
  double amount_;
};
KESTREL_REGISTER_COMPONENT(Shaper, OffsetShaper)

struct ClampConfig {
  double low = 0.0;
  double high = 1.0;
};

// The current form: a config struct, a rule across its parameters, and a context.
class ClampShaper final : public Shaper {
 public:
  static ComponentSpec spec() {
    ConfigSpec<ClampConfig> c;
    c.param("low", &ClampConfig::low).describe("lower bound");
    c.param("high", &ClampConfig::high).describe("upper bound");
    c.rule("low <= high", {"low", "high"}, [](const ClampConfig& k) { return k.low <= k.high; });
    return ComponentSpec("clamp", "Limits to a range").config(std::move(c));
  }
  explicit ClampShaper(const ComponentInit& init) : cfg_(init.config<ClampConfig>()), seed_(init.seed()) {
    init.log().debug("clamp {} to [{}, {}]", init.name(), cfg_.low, cfg_.high);
  }
  double shape(double v) const override { return std::clamp(v, cfg_.low, cfg_.high); }
  std::uint64_t seed() const { return seed_; }

 private:
  ClampConfig cfg_;
  std::uint64_t seed_;
};
KESTREL_REGISTER_COMPONENT(Shaper, ClampShaper)

class Shape final : public Node {
 public:
  static constexpr Input<Number> kIn{"in"};
  static constexpr Output<Number> kOut{"out"};
  static NodeSpec spec() {
    return NodeSpec("shape", "Applies a shaper component to each number")
        .input(kIn, "numbers")
        .output(kOut, "shaped numbers")
        .param(component_param("shaper", "shaper", "offset").describe("how to shape"));
  }
  explicit Shape(NodeInit& init) : shaper_(init.make_component<Shaper>("shaper")) {}
  void process(Context& ctx) override {
    Number n = *ctx.get(kIn);
    n.value = shaper_->shape(n.value);
    ctx.publish(kOut, n);
  }

 private:
  std::shared_ptr<Shaper> shaper_;
};
KESTREL_REGISTER_NODE(Shape)

}  // namespace kestrel::test
