// Tap inputs: the builder wires them to the outputs their topic patterns select, each message
// arrives with the output it came from, and a graph fragment from the command line can add one.
#include <gmock/gmock.h>

#include "kestrel/testing/graphs.hpp"

using namespace kestrel;
using namespace kestrel::testing;
using ::testing::ElementsAre;

namespace {

const char* const kTapGraph = R"(nodes:
  - {id: src, type: counter_source, params: {rate_hz: 10, count: 2}}
  - {id: double, type: scale, params: {factor: 2}}
  - {id: sink, type: collector}
  - {id: blobs, type: blob_source, params: {rate_hz: 10, count: 1, size_bytes: 8}}
  - {id: blob_sink, type: blob_sink}
  - {id: spare, type: counter_source, params: {rate_hz: 10, count: 1}}
  - {id: tap, type: tap_log, params: {topics: "TOPICS"}}
connections:
  - {from: src.out, to: double.in}
  - {from: double.out, to: sink.in}
  - {from: blobs.out, to: blob_sink.in}
)";

std::string tap_graph(const std::string& topics) {
  std::string g = kTapGraph;
  return g.replace(g.find("TOPICS"), 6, topics);
}

std::vector<std::string> tapped(const RunResult& r) {
  return r.report.at("tap").at("log").get<std::vector<std::string>>();
}

}  // namespace

TEST(Taps, ByDefaultTakeEveryConnectedOutputButTheSkippedTypesInPublicationOrder) {
  auto r = run(tap_graph(""));
  ASSERT_EQ(r.outcome, RunOutcome::completed);
  // Not the blobs (the tap skips test.Blob by default), not `spare` (connected to nothing).
  EXPECT_THAT(tapped(r), ElementsAre("src.out:test.Number", "double.out:test.Number", "src.out:test.Number",
                                     "double.out:test.Number"));
  EXPECT_EQ(connection_stats(r, "src.out -> tap.in (tap)").drops, 0u);
  // A tap queues whatever the graph's default policy: it must not replace what it has not taken.
  EXPECT_EQ(connection_stats(r, "src.out -> tap.in (tap)").policy, "fifo 256");
}

TEST(Taps, PatternsSelectByTopicAndTakeAnyType) {
  auto all = run(tap_graph("*"));
  EXPECT_EQ(tapped(all).size(), 6u);  // 2 + 2 numbers, 1 blob, 1 spare
  auto some = run(tap_graph("/blobs/*, /spare/out"));
  EXPECT_THAT(tapped(some), ElementsAre("blobs.out:test.Blob", "spare.out:test.Number"));
  auto but = run(tap_graph("* !/double/*"));
  EXPECT_EQ(tapped(but).size(), 4u);
  for (const auto& line : tapped(but)) EXPECT_THAT(line, ::testing::Not(::testing::StartsWith("double.")));
}

TEST(Taps, TakeHandWiredConnectionsBesideTheirSelectionButEachOutputOnce) {
  std::string g = tap_graph("/src/out");
  g += "  - {from: spare.out, to: tap.in}\n";
  auto r = run(g);
  EXPECT_THAT(tapped(r), ElementsAre("src.out:test.Number", "spare.out:test.Number", "src.out:test.Number"));

  std::string twice = tap_graph("");
  twice += "  - {from: src.out, to: tap.in}\n  - {from: src.out, to: tap.in}\n";
  auto built = build(twice);
  EXPECT_FALSE(built.graph);
  EXPECT_THAT(messages(built), ::testing::Contains(::testing::HasSubstr("src.out is already connected to tap.in")));
}

TEST(Taps, AFragmentAddsANodeAsAnIncludedFileWouldWithErrorsAtItsLabel) {
  const std::string base = R"(nodes:
  - {id: src, type: counter_source, params: {rate_hz: 10, count: 1}}
  - {id: sink, type: collector}
connections:
  - {from: src.out, to: sink.in}
)";
  const auto source = GraphSource::from_string(base, "g.yaml");
  const auto fragment = GraphSource::from_string("nodes: [{id: rec, type: tap_log}]", "--record");
  auto built = build_graph(source, test_plugins().registry(), {}, {&fragment});
  ASSERT_TRUE(built.graph) << built.diagnostics.str();
  auto r = run_graph(*built.graph, test_plugins().registry(), {});
  EXPECT_THAT(r.report.at("rec").at("log").get<std::vector<std::string>>(), ElementsAre("src.out:test.Number"));

  const auto bad = GraphSource::from_string("nodes: [{id: rec, type: tap_log, params: {topic: x}}]", "--record");
  auto refused = build_graph(source, test_plugins().registry(), {}, {&bad});
  EXPECT_FALSE(refused.graph);
  EXPECT_THAT(refused.diagnostics.str(), ::testing::HasSubstr("--record:1:"));
}
