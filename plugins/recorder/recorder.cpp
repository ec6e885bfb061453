// The `recorder` node: writes every output it taps into an MCAP file of ROS 2 messages
// (docs/recording.md). Under lockstep it writes as part of each step, so that a run records every
// message and two runs give the same bytes; under realtime a writer thread does, behind a bounded
// queue, and the graph never waits for the disk.
#include <fmt/format.h>

#include <fstream>
#include <kestrel/mcap/write_queue.hpp>
#include <kestrel/plugin.hpp>
#include <set>
#include <sstream>
#include <thread>

#include "mcap_recording.hpp"

namespace kestrel::recorder {

struct RecorderConfig {
  std::string file;
  std::string topics;
  std::string compression = "zstd";
  std::int64_t chunk_size_kib = 1024;
  std::int64_t queue_size = 256;
};

class RecorderNode final : public Node {
 public:
  static constexpr Input<AnyMessage> kIn{"in"};

  static NodeSpec spec() {
    using C = RecorderConfig;
    ConfigSpec<C> c;
    c.required("file", &C::file).describe("the MCAP file written (created or replaced)");
    c.param("topics", &C::topics)
        .describe(
            "what is recorded: topic patterns /NODE/PORT separated by commas or spaces ('*' for every output, "
            "'!PATTERN' to leave some out); empty: every connected output but point clouds");
    c.param("compression", &C::compression).one_of({"zstd", "lz4", "none"}).describe("chunk compression");
    c.param("chunk_size_kib", &C::chunk_size_kib)
        .with_unit("KiB")
        .range(1, 1 << 20)
        .describe("uncompressed size of a chunk: a run cut short loses at most the chunk being filled");
    c.param("queue_size", &C::queue_size)
        .range(1, 1 << 20)
        .describe("realtime executor: messages waiting for the writer thread before new ones are dropped");
    return NodeSpec("recorder", "Records the outputs it taps into an MCAP file of ROS 2 messages")
        .details(
            "Each message is written as the ROS 2 messages it maps onto (docs/recording.md), on channels named "
            "/NODE/PORT, with cdr encoding, ros2msg schemas and the ros2 profile. Metadata 'kestrel' holds the "
            "version, seed, duration and executor; 'graph' the graph's text and its resolved parameters. "
            "Messages of a type with no ROS 2 mapping are counted in the report, not written.")
        .tap(kIn, "the outputs its topics select (or that a graph connects to it)",
             TapOptions{"topics", {"kestrel.PointCloud"}})  // intermediate: replay makes them again
        .config(std::move(c));
  }

  explicit RecorderNode(NodeInit& init)
      : cfg_(init.config<RecorderConfig>()),
        recording_(cfg_.file,
                   RecordingOptions{cfg_.compression, static_cast<std::uint64_t>(cfg_.chunk_size_kib) * 1024}),
        realtime_(init.realtime()),
        queue_(static_cast<std::size_t>(cfg_.queue_size)) {
    if (realtime_) writer_ = std::thread([this] { write_queued(); });
  }

  ~RecorderNode() override { stop_writer(); }

  void process(Context& ctx) override {
    if (!metadata_written_) write_metadata(ctx);
    const Envelope& e = ctx.envelope(kIn.name);
    warn_unrecorded(ctx.log(), e);
    if (realtime_)
      queue_.push(e);
    else
      recording_.record(e);
  }

  void finish(Context& ctx) override {
    if (!metadata_written_) write_metadata(ctx);
    stop_writer();
    const std::uint64_t dropped = queue_.dropped();
    if (realtime_) recording_.write_metadata("kestrel.recorder", {{"dropped", std::to_string(dropped)}});
    recording_.finish();
    if (!writer_error_.empty()) throw Error("writing " + cfg_.file + ": " + writer_error_);
    ReportSection section;
    recording_.report(section);
    section.info("file", cfg_.file)
        .metric("dropped", dropped, "messages", Better::lower)
        .markdown(fmt::format("Recorded {} ROS 2 messages on {} channels into `{}`; {} dropped, {} of "
                              "types with no ROS 2 mapping.\n",
                              recording_.messages(), recording_.channels(), cfg_.file, dropped,
                              recording_.unrecorded()));
    ctx.set_report_section(ctx.id(), section);
  }

 private:
  // Metadata comes first, so a file cut short still says what ran. Only what makes the run
  // reproducible goes in: not this file's own path, so that two identical runs give identical
  // bytes wherever they write.
  void write_metadata(Context& ctx) {
    metadata_written_ = true;
    nlohmann::json run = ctx.run_description();
    nlohmann::json& graph = run["graph"];
    nlohmann::json& self = graph["resolved"]["nodes"][ctx.id()];
    if (self.contains("params")) self["params"].erase("file");
    std::string text;
    if (std::ifstream in(graph.value("file", "")); in) {
      std::ostringstream all;
      all << in.rdbuf();
      text = all.str();
    }
    const auto number = [](const nlohmann::json& j) { return j.is_null() ? std::string() : j.dump(); };
    recording_.write_metadata("kestrel", {{"version", run["kestrel_version"].get<std::string>()},
                                          {"seed", number(graph["seed"])},
                                          {"duration_s", number(graph["duration_s"])},
                                          {"executor", graph["executor"].get<std::string>()},
                                          {"clock", graph["clock"].get<std::string>()}});
    recording_.write_metadata(
        "graph", {{"name", graph["name"].get<std::string>()}, {"text", text}, {"resolved", graph["resolved"].dump()}});
  }

  void warn_unrecorded(Logger& log, const Envelope& e) {
    if (ros2::can_encode(e.type) || !warned_.insert(std::string(e.type)).second) return;
    log.warn("{} messages (from {}.{}) have no ROS 2 mapping: they are counted, not recorded", e.type, e.source_node,
             e.source_port);
  }

  void write_queued() {
    while (auto e = queue_.pop()) {
      if (!writer_error_.empty()) continue;  // drain; the error is reported at finish
      try {
        recording_.record(*e);
      } catch (const std::exception& ex) {
        writer_error_ = ex.what();
      }
    }
  }

  void stop_writer() {
    queue_.close();
    if (writer_.joinable()) writer_.join();
  }

  RecorderConfig cfg_;
  McapRecording recording_;
  bool realtime_;
  mcap::WriteQueue<Envelope> queue_;
  std::thread writer_;
  std::string writer_error_;  // set by the writer thread, read after it joined
  bool metadata_written_ = false;
  std::set<std::string> warned_;
};
KESTREL_REGISTER_NODE(RecorderNode)

}  // namespace kestrel::recorder
