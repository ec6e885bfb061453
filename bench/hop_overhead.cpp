// Per-hop overhead of the runtime: a chain of N trivial relay nodes passing a 1 MB message.
//
//   lockstep:  wall time per message per hop (incremental cost of one more relay), and heap
//              bytes allocated per hop
//   realtime:  latency per hop across threads (p50 / p99), each relay on its own thread
//   both:      bytes copied per hop, proven by the sink comparing buffer addresses
#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <atomic>
#include <cstdlib>
#include <new>
#include <string>

#include "kestrel/runtime/graph.hpp"
#include "kestrel/runtime/plugin_host.hpp"
#include "kestrel/runtime/run.hpp"
#include "kestrel/testing/plugins.hpp"

// Counts every heap allocation in the process, plugins included.
namespace {
std::atomic<std::uint64_t> g_allocated_bytes{0};
}
void* operator new(std::size_t n) {
  g_allocated_bytes.fetch_add(n, std::memory_order_relaxed);
  if (void* p = std::malloc(n)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace {

using namespace kestrel;

constexpr int kMessageBytes = 1 << 20;

PluginHost& plugins() { return kestrel::testing::test_plugins(); }

// source -> relay_1 -> ... -> relay_n -> sink
GraphConfig chain(int relays, const std::string& executor, int messages, double rate_hz, bool reuse) {
  std::string yaml = fmt::format(
      "executor: {}\nnodes:\n  - {{id: src, type: blob_source, params: {{size_bytes: {}, rate_hz: {}, count: {}, "
      "reuse: {}}}}}\n",
      executor, kMessageBytes, rate_hz, messages, reuse);
  for (int i = 0; i < relays; ++i) yaml += fmt::format("  - {{id: r{}, type: blob_relay}}\n", i);
  yaml += "  - {id: sink, type: blob_sink}\nconnections:\n";
  std::string previous = "src";
  for (int i = 0; i < relays; ++i) {
    const std::string id = fmt::format("r{}", i);
    yaml += fmt::format("  - {{from: {}.out, to: {}.in, policy: fifo 256}}\n", previous, id);
    previous = id;
  }
  yaml += fmt::format("  - {{from: {}.out, to: sink.in, policy: fifo 256}}\n", previous);
  auto built = build_graph(GraphSource::from_string(yaml, "bench"), plugins().registry());
  if (!built.graph) {
    std::fputs(built.diagnostics.str().c_str(), stderr);
    std::abort();
  }
  return std::move(*built.graph);
}

double run_seconds(const GraphConfig& graph, RunResult* out = nullptr) {
  const auto start = std::chrono::steady_clock::now();
  RunResult r = run_graph(graph, plugins().registry());
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (out) *out = std::move(r);
  return s;
}

// Lockstep: the time one more relay adds to each message (chain of N minus chain of 0), so the
// source's and sink's own costs cancel out.
void BM_LockstepHop(benchmark::State& state) {
  const int relays = static_cast<int>(state.range(0));
  constexpr int kMessages = 20000;
  const GraphConfig base = chain(0, "lockstep", kMessages, 1000.0, true);
  const GraphConfig longer = chain(relays, "lockstep", kMessages, 1000.0, true);
  double per_hop_ns = 0;
  double alloc_per_hop = 0;
  std::uint64_t copied = 0;
  for (auto _ : state) {
    const double t0 = run_seconds(base);
    const auto bytes_before = g_allocated_bytes.load();
    RunResult r;
    const double t1 = run_seconds(longer, &r);
    const auto bytes_longer = g_allocated_bytes.load() - bytes_before;
    const auto before_base = g_allocated_bytes.load();
    run_seconds(base);
    const auto bytes_base = g_allocated_bytes.load() - before_base;
    per_hop_ns = (t1 - t0) * 1e9 / (static_cast<double>(kMessages) * relays);
    alloc_per_hop = (static_cast<double>(bytes_longer) - static_cast<double>(bytes_base)) /
                    (static_cast<double>(kMessages) * relays);
    copied = r.report.at("sink").at("bytes_copied").get<std::uint64_t>();
    if (r.report.at("sink").at("count") != kMessages) state.SkipWithError("messages lost");
  }
  state.counters["ns_per_hop"] = per_hop_ns;
  state.counters["alloc_bytes_per_hop"] = alloc_per_hop;
  state.counters["bytes_copied_per_hop"] = static_cast<double>(copied) / (static_cast<double>(kMessages) * relays);
}
BENCHMARK(BM_LockstepHop)->Arg(8)->Arg(32)->Unit(benchmark::kMillisecond)->Iterations(3);

// Realtime: every relay on its own thread; latency from the source's publication to the sink,
// divided by the number of hops. New 1 MB blobs each time, allocated before the clock starts.
void BM_RealtimeHop(benchmark::State& state) {
  const int relays = static_cast<int>(state.range(0));
  constexpr int kMessages = 2000;
  const GraphConfig graph = chain(relays, "realtime", kMessages, 1000.0, false);
  RunResult r;
  for (auto _ : state) run_seconds(graph, &r);
  const auto& sink = r.report.at("sink");
  const double hops = relays + 1;
  state.counters["p50_us_per_hop"] = sink.at("latency_ns").at("p50").get<double>() / hops / 1e3;
  state.counters["p99_us_per_hop"] = sink.at("latency_ns").at("p99").get<double>() / hops / 1e3;
  state.counters["bytes_copied_per_hop"] = sink.at("bytes_copied").get<double>() / (kMessages * hops);
  state.counters["delivered"] = sink.at("count").get<double>();
}
BENCHMARK(BM_RealtimeHop)->Arg(1)->Arg(8)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
