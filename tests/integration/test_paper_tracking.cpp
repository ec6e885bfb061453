// Six seconds of the paper's tracking graph: detection chain, Kalman tracker, both evaluators.
// Bounds: the paper's MOTA, and its 0.09 m target RMSE with a margin for a short run.
#include <gmock/gmock.h>

#include <optional>

#include "kestrel/runtime/graph.hpp"
#include "kestrel/runtime/plugin_host.hpp"
#include "kestrel/runtime/run.hpp"

using namespace kestrel;

TEST(PaperTracking, KeepsOneIdentityOnTheFigureEight) {
  PluginHost host;
  host.load_search_path();
  auto built = build_graph(GraphSource::from_file(KESTREL_SOURCE_DIR "/graphs/paper_tracking.yaml"), host.registry());
  ASSERT_TRUE(built.graph) << built.diagnostics.str();
  RunOptions options;
  options.duration_s = 6.0;
  const auto r = run_graph(*built.graph, host.registry(), options);
  ASSERT_EQ(r.outcome, RunOutcome::completed) << (r.errors.empty() ? "" : r.errors.front());
  const auto& t = r.report.at("tracking");
  EXPECT_EQ(t.at("frames"), 180);
  EXPECT_GE(t.at("mota").get<double>(), 0.999);
  EXPECT_EQ(t.at("idsw"), 0);
  EXPECT_LE(t.at("rmse_m").get<double>(), 0.12);
  EXPECT_EQ(t.at("selected_frames"), 180);

  // The greedy associator is a drop-in replacement for this single target.
  auto greedy = build_graph(GraphSource::from_file(KESTREL_SOURCE_DIR "/graphs/paper_tracking.yaml"), host.registry(),
                            {"tracker.associator={type: greedy, gate_m: 1.0}"});
  ASSERT_TRUE(greedy.graph) << greedy.diagnostics.str();
  options.duration_s = 2.0;
  const auto g = run_graph(*greedy.graph, host.registry(), options);
  EXPECT_GE(g.report.at("tracking").at("mota").get<double>(), 0.999);
}

namespace {

RunResult run_graph_file(const std::string& file, double duration, const std::vector<std::string>& overrides = {},
                         std::optional<std::uint64_t> seed = {}) {
  static PluginHost* host = [] {
    auto* h = new PluginHost();
    h->load_search_path();
    return h;
  }();
  auto built = build_graph(GraphSource::from_file(file), host->registry(), overrides);
  EXPECT_TRUE(built.graph) << built.diagnostics.str();
  if (!built.graph) return {};
  RunOptions options;
  options.duration_s = duration;
  options.seed = seed;
  return run_graph(*built.graph, host->registry(), options);
}

}  // namespace

TEST(TrackingScenarios, CoastsThroughATemporaryOcclusion) {
  // Ten frames without detections from t = 1 s: the track is predicted through and keeps its id.
  const auto r = run_graph_file(KESTREL_SOURCE_DIR "/graphs/tracking_occlusion.yaml", 3.0, {"occlusion.first_s=1.0"});
  const auto& t = r.report.at("tracking");
  EXPECT_EQ(t.at("idsw"), 0);
  EXPECT_EQ(t.at("fragmentations"), 0);
  EXPECT_GE(t.at("mota").get<double>(), 0.99);
}

TEST(TrackingScenarios, TwoCrossingIntrudersAreBothTracked) {
  const auto r = run_graph_file(KESTREL_SOURCE_DIR "/graphs/crossing_intruders.yaml", 7.0);
  const auto& t = r.report.at("tracking");
  EXPECT_EQ(t.at("num_objects"), 2 * 210);  // two objects in every frame
  EXPECT_EQ(t.at("mostly_tracked"), 2);
  EXPECT_GE(t.at("mota").get<double>(), 0.9);
}

// The particle tracker draws from seeded streams only: two lockstep runs give the same tracks,
// to the last bit, and another seed gives others.
TEST(TrackingScenarios, ParticleTrackingRunsAreBitIdenticalForASeed) {
  const std::string graph = KESTREL_SOURCE_DIR "/graphs/paper_tracking_particle.yaml";
  const auto first = run_graph_file(graph, 1.0);
  const auto second = run_graph_file(graph, 1.0);
  ASSERT_TRUE(first.report.contains("tracking"));
  EXPECT_EQ(first.report.at("tracking"), second.report.at("tracking"));
  const auto other = run_graph_file(graph, 1.0, {}, 2);
  EXPECT_NE(first.report.at("tracking").at("rmse_m"), other.report.at("tracking").at("rmse_m"));
}
