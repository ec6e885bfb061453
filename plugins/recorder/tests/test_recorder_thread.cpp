// The recorder's writer thread under the realtime executor, on a graph light enough for
// ThreadSanitizer (no renderer): an intruder publishing its ground truth at 500 Hz into a queue of
// two. The graph thread hands messages over and the writer thread writes them; what the writer
// cannot take in time is dropped and counted, and the file holds every message that was not.
// Label `threads`: `make test-tsan` runs it.
#include <gtest/gtest.h>

#include <filesystem>

#include "kestrel/mcap/reader.hpp"
#include "kestrel/runtime/graph.hpp"
#include "kestrel/runtime/plugin_host.hpp"
#include "kestrel/runtime/run.hpp"
#include "kestrel/testing/plugins.hpp"
#include "kestrel/testing/scratch_path.hpp"

using namespace kestrel;
namespace fs = std::filesystem;

TEST(RecorderThread, UnderRealtimeEveryMessageIsWrittenOrCountedAsDropped) {
  const fs::path dir = kestrel::testing::scratch_path("kestrel-recorder-thread");
  fs::create_directories(dir);
  const fs::path file = dir / "truth.mcap";
  PluginHost& plugins = kestrel::testing::built_plugins();
  const auto graph = GraphSource::from_string(
      "executor: realtime\n"
      "nodes:\n"
      "  - {id: intruder, type: intruder, params: {rate_hz: 500}}\n"
      "  - {id: recorder, type: recorder, params: {file: '" +
          file.string() + "', topics: '/intruder/truth', queue_size: 2, compression: zstd, chunk_size_kib: 4}}\n",
      "recorder_thread.yaml");
  auto built = build_graph(graph, plugins.registry());
  ASSERT_TRUE(built.graph) << built.diagnostics.str();
  built.graph->clock = ClockKind::wall;
  RunOptions options;
  options.duration_s = 1.0;
  const RunResult r = run_graph(*built.graph, plugins.registry(), options);
  ASSERT_NE(r.outcome, RunOutcome::failed) << (r.errors.empty() ? "" : r.errors.front());

  const auto& section = r.report.at("recorder");
  const auto written = section.at("messages").get<std::uint64_t>();
  const auto dropped = section.at("dropped").get<std::uint64_t>();
  mcap::Reader reader(file);
  EXPECT_EQ(reader.summary().statistics.message_count, written);
  std::uint64_t in_file = 0;
  reader.read_messages({}, [&](const mcap::MessageView&) { ++in_file; });
  EXPECT_EQ(in_file, written);
  // Each truth is one message and one marker array: about 500 of each in a second, all accounted for.
  EXPECT_GT(written, 100u);
  EXPECT_GE(written / 2 + dropped, 400u);
}
