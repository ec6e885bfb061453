// Nodes that pass Counted messages around and record the address of every message they see,
// so a test can check that one published object reaches every subscriber uncopied.
#include <cstdint>
#include <kestrel/plugin.hpp>
#include <vector>

#include "test_messages.hpp"

namespace kestrel::test {

KESTREL_REGISTER_MESSAGE(Counted)

namespace {

std::uint64_t address(const void* p) { return static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(p)); }

}  // namespace

class CountedSource final : public Node {
 public:
  static constexpr Output<Counted> kOut{"out"};
  static NodeSpec spec() {
    return NodeSpec("counted_source", "Publishes Counted messages 0, 1, 2, ... and records their addresses")
        .output(kOut, "the messages")
        .param(param("rate_hz", 100.0).with_unit("Hz").range(0.001, 1e6).describe("publication rate"))
        .param(param("count", 10).at_least(1).describe("messages to publish"));
  }
  explicit CountedSource(NodeInit& init)
      : count_(init.param<std::int64_t>("count")), copies_at_start_(Counted::copies().load()) {
    init.set_rate(init.param<double>("rate_hz"));
  }
  void tick(Context& ctx) override {
    auto message = std::make_shared<const Counted>(next_++);
    addresses_.push_back(address(message.get()));
    ctx.publish(kOut, std::move(message));
    if (next_ == count_) ctx.end_of_stream();
  }
  void finish(Context& ctx) override {
    // Every node has processed its last message by now: copies made anywhere in this run count.
    ctx.set_report_section(ctx.id(),
                           ReportSection()
                               .quantity("addresses", addresses_)
                               .metric("copies", Counted::copies().load() - copies_at_start_, "", Better::lower));
  }

 private:
  std::int64_t count_;
  std::uint64_t copies_at_start_;
  std::int64_t next_ = 0;
  std::vector<std::uint64_t> addresses_;
};
KESTREL_REGISTER_NODE(CountedSource)

class CountedRelay final : public Node {
 public:
  static constexpr Input<Counted> kIn{"in"};
  static constexpr Output<Counted> kOut{"out"};
  static NodeSpec spec() {
    return NodeSpec("counted_relay", "Republishes each Counted message (the same shared object)")
        .input(kIn, "messages")
        .output(kOut, "the same messages");
  }
  explicit CountedRelay(NodeInit&) {}
  void process(Context& ctx) override { ctx.publish(kOut, ctx.get(kIn)); }
};
KESTREL_REGISTER_NODE(CountedRelay)

class CountedSink final : public Node {
 public:
  static constexpr Input<Counted> kIn{"in"};
  static NodeSpec spec() {
    return NodeSpec("counted_sink", "Records the index and address of every Counted message").input(kIn, "messages");
  }
  explicit CountedSink(NodeInit&) {}
  void process(Context& ctx) override {
    const auto m = ctx.get(kIn);
    indices_.push_back(m->index);
    addresses_.push_back(address(m.get()));
  }
  void finish(Context& ctx) override {
    ctx.set_report_section(ctx.id(), ReportSection().quantity("indices", indices_).quantity("addresses", addresses_));
  }

 private:
  std::vector<std::int64_t> indices_;
  std::vector<std::uint64_t> addresses_;
};
KESTREL_REGISTER_NODE(CountedSink)

// Several inputs: `a` and `b` trigger, `c` is read as its newest value. Records what each call
// saw on every input and republishes the triggering message.
class CountedJoin final : public Node {
 public:
  static constexpr Input<Counted> kA{"a"};
  static constexpr Input<Counted> kB{"b"};
  static constexpr Input<Counted> kC{"c"};
  static constexpr Output<Counted> kOut{"out"};
  static NodeSpec spec() {
    return NodeSpec("counted_join", "Records the Counted messages on two triggering inputs and one latest input")
        .input(kA, "triggers")
        .input(kB, "triggers")
        .input(kC, "read as its newest value", {.trigger = Trigger::latest})
        .output(kOut, "the triggering message, republished");
  }
  explicit CountedJoin(NodeInit&) {}
  void process(Context& ctx) override {
    const auto& in = ctx.triggered_by(kA) ? kA : kB;
    const auto m = ctx.get(in);
    Seen& seen = ctx.triggered_by(kA) ? a_ : b_;
    seen.indices.push_back(m->index);
    seen.addresses.push_back(address(m.get()));
    if (const auto c = ctx.get(kC)) {
      c_.indices.push_back(c->index);
      c_.addresses.push_back(address(c.get()));
    }
    ctx.publish(kOut, m);
  }
  void finish(Context& ctx) override {
    ReportSection section;
    for (const auto& [name, seen] : {std::pair{"a", &a_}, {"b", &b_}, {"c", &c_}})
      section.quantity(std::string(name) + ".indices", seen->indices)
          .quantity(std::string(name) + ".addresses", seen->addresses);
    ctx.set_report_section(ctx.id(), section);
  }

 private:
  struct Seen {
    std::vector<std::int64_t> indices;
    std::vector<std::uint64_t> addresses;
  };
  Seen a_, b_, c_;
};
KESTREL_REGISTER_NODE(CountedJoin)

}  // namespace kestrel::test
