// Six seconds of the paper's tracking graph: detection chain, tracker (Kalman filter), both evaluators;
// and the tracking scenarios.
// Bounds: the paper's MOTA, and a filter that is no worse than the detections it is fed (the
// paper's 0.09 m target RMSE is not reached, docs/tracking.md says why; today's figure is
// tracked by bench/paper_accuracy.cpp).
#include <gmock/gmock.h>

#include <cmath>
#include <optional>

#include "kestrel/runtime/graph.hpp"
#include "kestrel/runtime/plugin_host.hpp"
#include "kestrel/runtime/run.hpp"
#include "kestrel/testing/plugins.hpp"

using namespace kestrel;

TEST(PaperTracking, KeepsOneIdentityOnTheFigureEight) {
  PluginHost& host = kestrel::testing::built_plugins();
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
  // Filtering noisy detections of a smooth path averages their noise down: the selected track's
  // error is below the error of the detections themselves.
  const auto& d = r.report.at("detection").at("rmse_m");
  const double detection_rmse = std::sqrt(std::pow(d.at("x").get<double>(), 2) + std::pow(d.at("y").get<double>(), 2) +
                                          std::pow(d.at("z").get<double>(), 2));
  EXPECT_GT(t.at("rmse_m").get<double>(), 0.0);
  EXPECT_LT(t.at("rmse_m").get<double>(), detection_rmse);
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
  return kestrel::testing::run_built_graph(GraphSource::from_file(file), duration, overrides, seed);
}

}  // namespace

TEST(TrackingScenarios, CoastsThroughATemporaryOcclusion) {
  // Ten frames without detections from t = 1 s: the track is predicted through and keeps its id.
  const auto r = run_graph_file(KESTREL_SOURCE_DIR "/graphs/tracking_occlusion.yaml", 3.0, {"occlusion.first_s=1.0"});
  // The blackout happened: the tracker saw exactly its ten empty frames, and its target coasted
  // through all ten on its prediction.
  const auto& seen = r.report.at("tracker");
  EXPECT_EQ(seen.at("frames"), 90);
  EXPECT_EQ(seen.at("empty_frames"), 10);
  EXPECT_EQ(seen.at("target_coasted_frames"), 10);
  const auto& t = r.report.at("tracking");
  EXPECT_EQ(t.at("idsw"), 0);
  EXPECT_EQ(t.at("fragmentations"), 0);
  EXPECT_GE(t.at("mota").get<double>(), 0.99);
  EXPECT_EQ(t.at("target").at("on_target"), 90);
}

TEST(TrackingScenarios, TwoCrossingIntrudersAreBothTracked) {
  const auto r = run_graph_file(KESTREL_SOURCE_DIR "/graphs/crossing_intruders.yaml", 7.0);
  const auto& t = r.report.at("tracking");
  EXPECT_EQ(t.at("num_objects"), 2 * 210);  // two objects in every frame
  EXPECT_EQ(t.at("mostly_tracked"), 2);
  // The far intruder can be hidden, or merged with the near one into one cluster, at most while
  // the two silhouettes (0.63 m wide, at 5 m and 6 m, each flying at 0.5 m/s the other way)
  // come within one matching block (7 px at fx = 304 px: the matcher joins what a block spans)
  // of each other across the image, and each intruder may change identity once where they
  // cross; every other frame of both is a match.
  const double half_widths_rad = 0.315 / 5.0 + 0.315 / 6.0;
  const double block_rad = 7.0 / 304.0;
  const double closing_rad_per_s = 0.5 / 5.0 + 0.5 / 6.0;
  const double hidden_frames = 30.0 * (2.0 * half_widths_rad + 2.0 * block_rad) / closing_rad_per_s;
  EXPECT_GE(t.at("mota").get<double>(), 1.0 - (hidden_frames + 2.0) / (2 * 210));
}

// One graph, two filters: the YAML alone (here --set) swaps the Kalman filter for the particle
// filter, and gives the same tracks, to the last bit, as the particle graph in graphs/.
TEST(TrackingScenarios, TheYamlAloneSwitchesKalmanAndParticleFilters) {
  const std::string kalman = KESTREL_SOURCE_DIR "/graphs/paper_tracking.yaml";
  const auto by_kalman = run_graph_file(kalman, 1.0);
  const auto by_particles = run_graph_file(kalman, 1.0, {"tracker.filter={type: particle, r: 0.005}"});
  const auto particle_graph = run_graph_file(KESTREL_SOURCE_DIR "/graphs/paper_tracking_particle.yaml", 1.0);
  ASSERT_TRUE(by_particles.report.contains("tracking"));
  EXPECT_NE(by_kalman.report.at("tracking").at("rmse_m"), by_particles.report.at("tracking").at("rmse_m"));
  EXPECT_EQ(by_particles.report.at("tracking"), particle_graph.report.at("tracking"));
  // And back: the particle graph with the Kalman filter is the Kalman graph.
  const auto back = run_graph_file(KESTREL_SOURCE_DIR "/graphs/paper_tracking_particle.yaml", 1.0,
                                   {"tracker.filter={type: kalman, q: 200}"});
  EXPECT_EQ(back.report.at("tracking"), by_kalman.report.at("tracking"));
}

// The particle filter draws from seeded streams only: two lockstep runs give the same tracks,
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
