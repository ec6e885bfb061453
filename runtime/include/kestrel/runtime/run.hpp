#pragma once
// Running a validated graph: the executors, the statistics they keep and the report they write.
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "kestrel/registry.hpp"
#include "kestrel/runtime/graph.hpp"
#include "kestrel/runtime/histogram.hpp"

namespace kestrel {

struct RunOptions {
  std::optional<double> duration_s;   ///< overrides the graph's duration
  std::optional<std::uint64_t> seed;  ///< overrides the graph's seed
  std::filesystem::path report_dir;   ///< write report.json and report.md here if set
  bool progress = false;              ///< a status line on stderr every second
  /// Set from elsewhere (a signal handler, a test) to stop the run cleanly.
  const std::atomic<bool>* stop_flag = nullptr;
  /// Called once, on the run's own thread, when the run is under way: every node is built and
  /// every source has been called at least once (or has ended). Not called if no node could start
  /// or the run ended before.
  std::function<void()> on_running;
};

struct NodeStats {
  std::string id;
  std::string type;
  std::uint64_t messages_in = 0;
  std::uint64_t messages_out = 0;
  std::uint64_t drops = 0;   ///< at this node's inputs
  std::uint64_t errors = 0;  ///< exceptions caught from this node
  std::uint64_t calls = 0;
  DurationHistogram processing;  ///< time inside process() and tick()
  /// From the capture stamp of each stamped message the node published to its publication, on
  /// the run's clock: under the realtime executor, how old the data is when it leaves the node.
  DurationHistogram latency;
};

struct ConnectionStats {
  std::string label;
  std::string policy;
  bool delayed = false;
  std::uint64_t delivered = 0;
  std::uint64_t drops = 0;
  std::size_t high_water = 0;  ///< most messages ever waiting in the queue
};

enum class RunOutcome {
  completed,  ///< reached its duration, or every source ended
  stopped,    ///< a stop was requested (signal, node) and the graph drained
  failed,     ///< a node error under on_error: stop
};

struct RunResult {
  RunOutcome outcome = RunOutcome::completed;
  std::vector<std::string> errors;  ///< "node 'x' (type): message"
  double sim_time_s = 0.0;
  double wall_time_s = 0.0;
  std::vector<NodeStats> nodes;
  std::vector<ConnectionStats> connections;
  nlohmann::json report;  ///< what report.json holds

  /// 0 unless the run failed.
  int exit_code() const { return outcome == RunOutcome::failed ? 1 : 0; }
};

/// Runs `graph` with the executor it names. Never throws for node errors: they end up in
/// RunResult::errors. Throws kestrel::Error if the report directory cannot be written.
RunResult run_graph(const GraphConfig& graph, const Registry& registry, const RunOptions& options = {});

/// The per-node and per-connection statistics as an aligned text table.
std::string format_stats(const RunResult& result);

}  // namespace kestrel
