// run, validate and dot: the commands that load a graph.
#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <iostream>

#include "commands.hpp"
#include "kestrel/runtime/graph.hpp"
#include "kestrel/runtime/plugin_host.hpp"
#include "kestrel/runtime/run.hpp"

namespace kestrel::cli {

namespace {

std::atomic<bool> g_stop{false};

void on_signal(int) {
  if (g_stop.exchange(true)) _exit(130);  // a second signal: the user insists, leave now
  static const char msg[] = "\n[kestrel] stopping: draining queues (signal again to quit at once)\n";
  [[maybe_unused]] auto n = write(STDERR_FILENO, msg, sizeof msg - 1);
}

void install_signal_handlers() {
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

struct LoadedGraph {
  std::unique_ptr<PluginHost> plugins;
  std::optional<GraphConfig> graph;
};

// Reads the graph, loads the plugins it may need, validates. Prints every problem.
LoadedGraph load(const GraphArgs& args) {
  LoadedGraph loaded;
  const GraphSource source = GraphSource::from_file(args.graph);
  loaded.plugins = std::make_unique<PluginHost>();
  loaded.plugins->load_search_path(source.plugin_paths());
  for (const auto& e : loaded.plugins->errors()) spdlog::warn("{}", e.message);
  BuildResult result = build_graph(source, loaded.plugins->registry(), args.overrides);
  std::fputs(result.diagnostics.str().c_str(), stderr);
  if (result.diagnostics.has_errors())
    std::fprintf(stderr, "%s: %zu error(s); the graph was not run\n", args.graph.c_str(),
                 result.diagnostics.error_count());
  loaded.graph = std::move(result.graph);
  return loaded;
}

}  // namespace

int validate_command(const GraphArgs& args) {
  auto loaded = load(args);
  if (!loaded.graph) return kInvalidGraph;
  std::printf("%s: valid (%zu nodes, %zu connections)\n", args.graph.c_str(), loaded.graph->nodes.size(),
              loaded.graph->connections.size());
  return kOk;
}

int dot_command(const GraphArgs& args, const std::string& output) {
  auto loaded = load(args);
  if (!loaded.graph) return kInvalidGraph;
  const std::string dot = to_dot(*loaded.graph);
  if (output.empty()) {
    std::fputs(dot.c_str(), stdout);
    return kOk;
  }
  std::ofstream out(output);
  out << dot;
  if (!out) {
    spdlog::error("cannot write {}", output);
    return kUsage;
  }
  return kOk;
}

int run_command(const RunArgs& args) {
  auto loaded = load(args);
  if (!loaded.graph) return kInvalidGraph;
  if (args.executor == "realtime") {
    loaded.graph->executor = ExecutorKind::realtime;
    loaded.graph->clock = ClockKind::wall;
  } else if (args.executor == "lockstep") {
    loaded.graph->executor = ExecutorKind::lockstep;
    loaded.graph->clock = ClockKind::simulated;
  }
  install_signal_handlers();
  RunOptions options;
  options.duration_s = args.duration_s;
  options.seed = args.seed;
  options.report_dir = args.report_dir;
  options.progress = args.progress;
  options.stop_flag = &g_stop;
  // On stderr, so that what users parse on stdout does not change; scripts and tests wait for it.
  options.on_running = [] {
    std::fputs("[kestrel] running (SIGINT or SIGTERM stops the run cleanly)\n", stderr);
    std::fflush(stderr);
  };
  RunResult result;
  try {
    result = run_graph(*loaded.graph, loaded.plugins->registry(), options);
  } catch (const Error& e) {
    spdlog::error("{}", e.what());
    return kRunFailed;
  }
  if (args.stats) std::fputs(format_stats(result).c_str(), stdout);
  if (!args.report_dir.empty()) spdlog::info("report written to {}/report.json and report.md", args.report_dir);
  if (result.outcome == RunOutcome::failed) {
    spdlog::error("run failed after {:.2f} s with {} node error(s)", result.sim_time_s, result.errors.size());
    return kRunFailed;
  }
  std::uint64_t errors = 0;
  for (const auto& n : result.nodes) errors += n.errors;
  if (errors > 0) spdlog::warn("{} message(s) dropped by node errors (on_error: skip)", errors);
  spdlog::info("run {} at t = {:.2f} s ({:.2f} s wall)",
               result.outcome == RunOutcome::stopped ? "stopped" : "completed", result.sim_time_s, result.wall_time_s);
  return kOk;
}

}  // namespace kestrel::cli
