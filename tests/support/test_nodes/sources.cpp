// Timer-driven sources of numbers and blobs.
#include <chrono>
#include <kestrel/plugin.hpp>

#include "test_messages.hpp"

namespace kestrel::test {

KESTREL_REGISTER_MESSAGE(Number)
KESTREL_REGISTER_MESSAGE(Blob)

class CounterSource final : public Node {
 public:
  static constexpr Output<Number> kOut{"out"};
  static NodeSpec spec() {
    return NodeSpec("counter_source", "Publishes 0, 1, 2, ... (plus optional Gaussian noise) at a fixed rate")
        .output(kOut, "the numbers")
        .param(param("rate_hz", 10.0).with_unit("Hz").range(0.001, 1e6).describe("publication rate"))
        .param(param("count", 0).at_least(0).describe("messages to publish; 0 = until the run ends"))
        .param(param("noise", 0.0).at_least(0.0).describe("standard deviation of noise added to each value"));
  }
  explicit CounterSource(NodeInit& init)
      : count_(init.param<std::int64_t>("count")),
        noise_(0.0, std::max(init.param<double>("noise"), 1e-300)),
        noisy_(init.param<double>("noise") > 0) {
    init.set_rate(init.param<double>("rate_hz"));
  }
  void tick(Context& ctx) override {
    const double noise = noisy_ ? noise_(ctx.rng()) : 0.0;
    ctx.publish(kOut, Number{next_, static_cast<double>(next_) + noise});
    if (++next_ == count_) ctx.end_of_stream();
  }

 private:
  std::int64_t count_;
  std::int64_t next_ = 0;
  std::normal_distribution<double> noise_;
  bool noisy_;
};
KESTREL_REGISTER_NODE(CounterSource)

class BlobSource final : public Node {
 public:
  static constexpr Output<Blob> kOut{"out"};
  static NodeSpec spec() {
    return NodeSpec("blob_source", "Publishes a block of bytes at a fixed rate")
        .output(kOut, "the blobs")
        .param(param("rate_hz", 10.0).with_unit("Hz").range(0.001, 1e6).describe("publication rate"))
        .param(param("size_bytes", 1024).range(0, 1 << 30).with_unit("B").describe("size of each blob"))
        .param(param("count", 0).at_least(0).describe("blobs to publish; 0 = until the run ends"))
        .param(param("reuse", false).describe("publish one shared blob again and again instead of a new one"));
  }
  explicit BlobSource(NodeInit& init)
      : size_(static_cast<std::size_t>(init.param<std::int64_t>("size_bytes"))),
        count_(init.param<std::int64_t>("count")) {
    init.set_rate(init.param<double>("rate_hz"));
    if (init.param<bool>("reuse")) shared_ = make();
  }
  void tick(Context& ctx) override {
    ctx.publish(kOut, shared_ ? shared_ : make());
    if (++sent_ == count_) ctx.end_of_stream();
  }

 private:
  std::shared_ptr<const Blob> make() const {
    auto blob = std::make_shared<Blob>();
    blob->bytes.assign(size_, static_cast<std::uint8_t>(sent_));
    blob->origin = blob->bytes.data();
    blob->created_ns = std::chrono::steady_clock::now().time_since_epoch().count();
    return blob;
  }

 private:
  std::size_t size_;
  std::int64_t count_;
  std::int64_t sent_ = 0;
  std::shared_ptr<const Blob> shared_;
};
KESTREL_REGISTER_NODE(BlobSource)

}  // namespace kestrel::test
