// Sinks that record what reached them into the run report.
#include <chrono>
#include <cstring>
#include <kestrel/plugin.hpp>
#include <kestrel/runtime/histogram.hpp>

#include "test_messages.hpp"

namespace kestrel::test {

class Collector final : public Node {
 public:
  static constexpr Input<Number> kIn{"in"};
  static NodeSpec spec() {
    return NodeSpec("collector", "Records every number it receives into the report, under its node id")
        .input(kIn, "numbers")
        .param(param("keep", 100000).at_least(0).describe("values kept in the report (the count is always exact)"));
  }
  explicit Collector(NodeInit& init) : keep_(static_cast<std::size_t>(init.param<std::int64_t>("keep"))) {}
  void process(Context& ctx) override {
    const auto n = ctx.get(kIn);
    ++count_;
    // Bit-exact fingerprint of everything received, in order.
    std::uint64_t bits = 0;
    std::memcpy(&bits, &n->value, sizeof bits);
    checksum_ = (checksum_ ^ bits ^ static_cast<std::uint64_t>(n->index)) * 1099511628211ull;
    if (values_.size() < keep_) {
      values_.push_back(n->value);
      indices_.push_back(n->index);
      stamps_.push_back(to_seconds(ctx.now()));
    }
  }
  void finish(Context& ctx) override {
    ctx.set_report_section(ctx.id(), ReportSection()
                                         .metric("count", count_, "messages", Better::higher)
                                         .quantity("checksum", checksum_)
                                         .quantity("values", values_)
                                         .quantity("indices", indices_)
                                         .quantity("times_s", stamps_, "s"));
    if (ctx.keeps_artifacts()) {
      std::string csv = "index,value\n";
      for (std::size_t i = 0; i < values_.size(); ++i)
        csv += std::to_string(indices_[i]) + "," + std::to_string(values_[i]) + "\n";
      ctx.add_artifact(ctx.id() + ".csv", csv, "the values received");
    }
  }

 private:
  std::size_t keep_;
  std::uint64_t count_ = 0;
  std::uint64_t checksum_ = 1469598103934665603ull;
  std::vector<double> values_;
  std::vector<std::int64_t> indices_;
  std::vector<double> stamps_;
};
KESTREL_REGISTER_NODE(Collector)

// A tap: lists, in order, every message it received with the output it came from, as a recorder
// sees them.
class TapLog final : public Node {
 public:
  static constexpr Input<AnyMessage> kIn{"in"};
  static NodeSpec spec() {
    return NodeSpec("tap_log", "Lists each message it taps as NODE.PORT:TYPE, in the order received")
        .tap(kIn, "every output its topics select", TapOptions{"topics", {"test.Blob"}})
        .param(param("topics", std::string()).describe("topic patterns (empty: every connected output but blobs)"));
  }
  explicit TapLog(NodeInit&) {}
  void process(Context& ctx) override {
    const Envelope& e = ctx.envelope(kIn.name);
    log_.push_back(std::string(e.source_node) + "." + std::string(e.source_port) + ":" + std::string(e.type));
  }
  void finish(Context& ctx) override { ctx.set_report_section(ctx.id(), ReportSection().info("log", log_)); }

 private:
  std::vector<std::string> log_;
};
KESTREL_REGISTER_NODE(TapLog)

class BlobSink final : public Node {
 public:
  static constexpr Input<Blob> kIn{"in"};
  static NodeSpec spec() {
    return NodeSpec("blob_sink", "Counts blobs, checks they were never copied and times their journey")
        .input(kIn, "blobs");
  }
  explicit BlobSink(NodeInit&) {}
  void process(Context& ctx) override {
    const auto blob = ctx.get(kIn);
    ++count_;
    if (blob->bytes.data() != blob->origin) bytes_copied_ += blob->bytes.size();
    latency_.record(std::chrono::steady_clock::now().time_since_epoch().count() - blob->created_ns);
  }
  void finish(Context& ctx) override {
    ctx.set_report_section(
        ctx.id(), ReportSection()
                      .quantity("count", count_)
                      .metric("bytes_copied", bytes_copied_, "B", Better::lower)
                      .metric("latency_ns", {{"p50", latency_.quantile(0.5)}, {"p99", latency_.quantile(0.99)}}, "ns",
                              Better::lower));
  }

 private:
  std::uint64_t count_ = 0;
  std::uint64_t bytes_copied_ = 0;
  DurationHistogram latency_;
};
KESTREL_REGISTER_NODE(BlobSink)

}  // namespace kestrel::test
