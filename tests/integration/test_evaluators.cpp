// The detection and tracking evaluators as nodes, on a scene whose answer is known, under both
// executors. Under realtime the detections and tracks reach the evaluators late, through a slow
// node, while the truth comes straight: the evaluators must pair them by capture time.
#include <gmock/gmock.h>

#include <cmath>

#include "kestrel/runtime/graph.hpp"
#include "kestrel/runtime/plugin_host.hpp"
#include "kestrel/runtime/run.hpp"
#include "kestrel/testing/plugins.hpp"

using namespace kestrel;

namespace {

PluginHost& plugins() { return kestrel::testing::built_and_test_plugins(); }

RunResult run(const std::string& yaml) {
  auto built = build_graph(GraphSource::from_string(yaml, "g.yaml"), plugins().registry());
  EXPECT_TRUE(built.graph) << built.diagnostics.str();
  if (!built.graph) return {};
  return run_graph(*built.graph, plugins().registry());
}

constexpr int kFrames = 30;
constexpr double kDelayS = 0.015;

// 30 frames at 50 Hz; the detection and the track are off by (0.1, -0.2, 0.3) m; every fifth
// frame has no detection; the tracking evaluator skips frames captured before 0.19 s (k < 10).
std::string scene_graph(const std::string& executor) {
  return "executor: " + executor + R"(
nodes:
  - {id: scene, type: scene_source, params: {rate_hz: 50, count: 30, offset_m: [0.1, -0.2, 0.3], miss_every: 5}}
  - {id: slow_detections, type: detections_delay, params: {delay_ms: 15}}
  - {id: slow_tracks, type: tracks_delay, params: {delay_ms: 15}}
  - {id: score, type: detection_evaluator, params: {max_lag_s: 0.1}}
  - {id: tracking_score, type: mot_evaluator, params: {max_lag_s: 0.1, skip_first_s: 0.19}}
connections:
  - {from: scene.truth, to: score.truth, policy: fifo 64}
  - {from: scene.detections, to: slow_detections.in, policy: fifo 64}
  - {from: slow_detections.out, to: score.detections, policy: fifo 64}
  - {from: scene.truth, to: tracking_score.truth, policy: fifo 64}
  - {from: scene.tracks, to: slow_tracks.in, policy: fifo 64}
  - {from: slow_tracks.out, to: tracking_score.tracks, policy: fifo 64}
)";
}

}  // namespace

class Evaluators : public ::testing::TestWithParam<std::string> {};

TEST_P(Evaluators, ScoreAKnownSceneWhateverTheArrivalOrder) {
  const bool realtime = GetParam() == "realtime";
  const auto r = run(scene_graph(GetParam()));
  ASSERT_EQ(r.outcome, RunOutcome::completed) << (r.errors.empty() ? "" : r.errors.front());
  for (const auto& c : r.connections) EXPECT_EQ(c.drops, 0u) << c.label;

  // Detections: every frame paired with its truth and scored; misses on k % 5 == 4.
  const auto& d = r.report.at("detection");
  EXPECT_EQ(d.at("frames"), kFrames);
  EXPECT_EQ(d.at("tp"), 24);
  EXPECT_EQ(d.at("fn"), 6);
  EXPECT_EQ(d.at("fp"), 0);
  EXPECT_DOUBLE_EQ(d.at("precision").get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(d.at("recall").get<double>(), 0.8);
  EXPECT_NEAR(d.at("rmse_m").at("x").get<double>(), 0.1, 1e-9);
  EXPECT_NEAR(d.at("rmse_m").at("y").get<double>(), 0.2, 1e-9);
  EXPECT_NEAR(d.at("rmse_m").at("z").get<double>(), 0.3, 1e-9);
  EXPECT_NEAR(d.at("mean_error_m").at("y").get<double>(), -0.2, 1e-9);
  EXPECT_EQ(d.at("unpaired").at("messages"), 0);
  EXPECT_EQ(d.at("unpaired").at("truths"), 0);

  // Tracks: frames 10..29 scored, one identity on the intruder throughout.
  const auto& t = r.report.at("tracking");
  EXPECT_EQ(t.at("frames"), kFrames - 10);
  EXPECT_EQ(t.at("num_objects"), kFrames - 10);
  EXPECT_DOUBLE_EQ(t.at("mota").get<double>(), 1.0);
  EXPECT_EQ(t.at("idsw"), 0);
  EXPECT_EQ(t.at("selected_frames"), kFrames - 10);
  EXPECT_NEAR(t.at("rmse_m").get<double>(), std::sqrt(0.01 + 0.04 + 0.09), 1e-9);
  EXPECT_EQ(t.at("target").at("on_target"), kFrames - 10);
  EXPECT_EQ(t.at("unpaired").at("messages"), 0);
  EXPECT_EQ(t.at("unpaired").at("truths"), 0);

  // The lag: none on the simulated clock; under realtime at least the slow node's delay (every
  // message left it 15 ms or more after its capture), within the search range.
  for (const auto* section : {&d, &t}) {
    ASSERT_FALSE(section->at("lag_s").is_null());
    const double lag = section->at("lag_s").get<double>();
    if (realtime) {
      EXPECT_GE(lag, kDelayS - 0.005);
      EXPECT_LT(lag, 0.1);
    } else {
      EXPECT_DOUBLE_EQ(lag, 0.0);
    }
  }
}

// Named after the executor: the realtime instance carries the CTest label `threads`.
INSTANTIATE_TEST_SUITE_P(Executors, Evaluators, ::testing::Values("lockstep", "realtime"),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });
