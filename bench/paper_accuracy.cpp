// Today's accuracy of the paper's graphs, as benchmark counters. The tests bound these figures
// by what the method must achieve (the paper's Table 1, the half-pixel depth bound, a tracker no
// worse than its detections); this benchmark records where they stand now, so that a change
// that moves them shows up run to run (docs/benchmarks.md). Lockstep runs: the counters are the
// same on every machine; the time is how long the run took.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdlib>
#include <string>

#include "kestrel/runtime/graph.hpp"
#include "kestrel/runtime/plugin_host.hpp"
#include "kestrel/runtime/run.hpp"
#include "kestrel/testing/plugins.hpp"

namespace {

using namespace kestrel;

PluginHost& plugins() { return kestrel::testing::built_plugins(); }

RunResult run(benchmark::State& state, const std::string& graph) {
  auto built = build_graph(GraphSource::from_file(KESTREL_SOURCE_DIR "/graphs/" + graph), plugins().registry());
  if (!built.graph) {
    state.SkipWithError(built.diagnostics.str().c_str());
    return {};
  }
  RunOptions options;
  options.duration_s = static_cast<double>(state.range(0));
  auto result = run_graph(*built.graph, plugins().registry(), options);
  if (result.outcome != RunOutcome::completed) state.SkipWithError("the run did not complete");
  return result;
}

void detection_counters(benchmark::State& state, const nlohmann::json& d) {
  state.counters["precision"] = d.at("precision").get<double>();
  state.counters["recall"] = d.at("recall").get<double>();
  for (const char* axis : {"x", "y", "z"})
    state.counters[std::string("rmse_") + axis + "_m"] = d.at("rmse_m").at(axis).get<double>();
}

// The detection chain at 5 m (Table 1's middle row).
void BM_PaperDetection(benchmark::State& state) {
  RunResult r;
  for (auto _ : state) r = run(state, "paper_detection.yaml");
  if (r.report.contains("detection")) detection_counters(state, r.report.at("detection"));
}
BENCHMARK(BM_PaperDetection)->Arg(4)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

// The Kalman tracker at r = 1 on that chain (the r sweep's reference point).
void BM_PaperTracking(benchmark::State& state) {
  RunResult r;
  for (auto _ : state) r = run(state, "paper_tracking.yaml");
  if (!r.report.contains("tracking")) return;
  detection_counters(state, r.report.at("detection"));
  const auto& t = r.report.at("tracking");
  state.counters["mota"] = t.at("mota").get<double>();
  state.counters["track_rmse_m"] = t.at("rmse_m").get<double>();
  state.counters["idsw"] = t.at("idsw").get<double>();
}
BENCHMARK(BM_PaperTracking)->Arg(6)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
