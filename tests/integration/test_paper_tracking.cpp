// Six seconds of the paper's tracking graph: detection chain, Kalman tracker, both evaluators.
// Bounds: the paper's MOTA, and its 0.09 m target RMSE with a margin for a short run.
#include <gmock/gmock.h>

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
