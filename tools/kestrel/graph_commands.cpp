// run, validate and dot: the commands that load a graph.
#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "command_errors.hpp"
#include "commands.hpp"
#include "graph_loading.hpp"
#include "kestrel/runtime/run.hpp"
#include "live_endpoint.hpp"
#include "output_files.hpp"

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

}  // namespace

int validate_command(const GraphArgs& args) {
  auto loaded = load_graph(args);
  if (!loaded.graph) return kInvalidGraph;
  std::printf("%s: valid (%zu nodes, %zu connections)\n", args.graph.c_str(), loaded.graph->nodes.size(),
              loaded.graph->connections.size());
  return kOk;
}

int dot_command(const GraphArgs& args, const std::string& output) {
  auto loaded = load_graph(args);
  if (!loaded.graph) return kInvalidGraph;
  const std::string dot = to_dot(*loaded.graph);
  if (output.empty()) {
    std::fputs(dot.c_str(), stdout);
    return kOk;
  }
  return run_command_body("dot", [&] {
    write_file(output, dot);
    return kOk;
  });
}

int run_command(const RunArgs& args) {
  // Before the graph loads (seconds, on a busy machine): a run stopped that early still ends
  // cleanly, with its report, instead of dying of the signal.
  install_signal_handlers();
  RunArgs with_extras = args;
  if (!args.record.empty()) {
    // JSON strings are YAML strings: any path or pattern goes through quoted.
    nlohmann::json params = {{"file", args.record}};
    if (args.topics) params["topics"] = *args.topics;
    with_extras.fragments.push_back(
        {"--record", "nodes: [{id: recorder, type: recorder, params: " + params.dump() + "}]"});
  } else if (args.topics && !args.dds) {
    spdlog::error("--topics chooses what --record records and --dds publishes; give one of them too");
    return kUsage;
  }
  if (args.dds) {
    std::uint32_t domain = 0;
    try {
      domain = dds_domain(args.dds_domain);
    } catch (const Error& e) {
      spdlog::error("{}", e.what());
      return kUsage;
    }
    const nlohmann::json params = {{"domain_id", domain}, {"publish", args.topics.value_or("")}};
    with_extras.fragments.push_back({"--dds", "nodes: [{id: dds, type: dds_bridge, params: " + params.dump() + "}]"});
  } else if (args.dds_domain) {
    spdlog::error("--dds-domain goes with --dds");
    return kUsage;
  }
  if (args.live) {
    const auto endpoint = parse_live_endpoint(*args.live);
    if (!endpoint) {
      spdlog::error("--live takes PORT or ADDRESS:PORT (0 to 65535), not '{}'", *args.live);
      return kUsage;
    }
    const nlohmann::json params = {{"port", endpoint->port}, {"address", endpoint->address}};
    with_extras.fragments.push_back(
        {"--live", "nodes: [{id: live, type: foxglove_bridge, params: " + params.dump() + "}]"});
  }
  auto loaded = load_graph(with_extras);
  if (!loaded.graph) return kInvalidGraph;
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
