#include <fmt/format.h>

#include <chrono>
#include <fstream>

#include "graph_record.hpp"
#include "kestrel/runtime/run.hpp"
#include "kestrel/version.hpp"
#include "lockstep_executor.hpp"
#include "realtime_executor.hpp"
#include "report_writer.hpp"

namespace kestrel {

namespace {

using detail::NodeRuntime;

const char* outcome_name(RunOutcome outcome) {
  switch (outcome) {
    case RunOutcome::completed:
      return "completed";
    case RunOutcome::stopped:
      return "stopped";
    case RunOutcome::failed:
      return "failed";
  }
  return "?";
}

void collect_stats(const detail::RunState& run, RunResult& result) {
  for (const auto& node : run.nodes) {
    NodeStats& s = result.nodes.emplace_back();
    s.id = node->id();
    s.type = node->type();
    s.messages_in = node->messages_in.load();
    s.messages_out = node->messages_out.load();
    s.errors = node->errors.load();
    s.calls = node->calls.load();
    s.drops = node->skipped_ticks;
    for (const auto& slot : node->inputs)
      if (slot.edge) s.drops += slot.edge->dropped;
    s.processing = node->processing;
    s.latency = node->latency;
  }
  for (const auto& edge : run.edges) {
    ConnectionStats& c = result.connections.emplace_back();
    c.label = edge->config->label;
    c.policy = edge->config->policy.str();
    c.delayed = edge->config->delayed;
    c.delivered = edge->delivered;
    c.drops = edge->dropped;
    c.high_water = edge->high_water;
  }
}

nlohmann::json stats_json(const RunResult& result) {
  auto us = [](std::int64_t ns) { return static_cast<double>(ns) / 1000.0; };
  nlohmann::json nodes = nlohmann::json::array();
  for (const auto& n : result.nodes) {
    nodes.push_back({{"id", n.id},
                     {"type", n.type},
                     {"messages_in", n.messages_in},
                     {"messages_out", n.messages_out},
                     {"drops", n.drops},
                     {"errors", n.errors},
                     {"calls", n.calls},
                     {"processing_us",
                      {{"p50", us(n.processing.quantile(0.5))},
                       {"p99", us(n.processing.quantile(0.99))},
                       {"max", us(n.processing.max())},
                       {"mean", n.processing.mean() / 1000.0}}},
                     {"latency_us", n.latency.count() == 0 ? nlohmann::json()
                                                           : nlohmann::json{{"p50", us(n.latency.quantile(0.5))},
                                                                            {"p99", us(n.latency.quantile(0.99))},
                                                                            {"max", us(n.latency.max())}}}});
  }
  nlohmann::json connections = nlohmann::json::array();
  for (const auto& c : result.connections) {
    connections.push_back({{"connection", c.label},
                           {"policy", c.policy},
                           {"delayed", c.delayed},
                           {"delivered", c.delivered},
                           {"drops", c.drops},
                           {"high_water", c.high_water}});
  }
  return {{"nodes", nodes}, {"connections", connections}};
}

}  // namespace

RunResult run_graph(const GraphConfig& graph, const Registry& registry, const RunOptions& options) {
  detail::RunState run(graph, registry, options);
  if (!options.report_dir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(options.report_dir, ec);
    if (ec) throw Error("cannot create report directory " + options.report_dir.string() + ": " + ec.message());
    run.report.set_artifact_dir(options.report_dir);
  }

  RunResult result;
  const auto wall_start = std::chrono::steady_clock::now();
  Time ended_at{0};
  if (run.instantiate()) {
    detail::Progress progress(run, options.progress);
    auto execute = [&](auto& executor) {
      run.executor = &executor;
      ended_at = executor.run(progress);
      progress.finish();
      for (NodeRuntime* node : run.order) node->call(NodeRuntime::Call::finish);
      run.executor = nullptr;
    };
    if (graph.executor == ExecutorKind::lockstep) {
      detail::LockstepExecutor executor(run);
      execute(executor);
    } else {
      detail::RealtimeExecutor executor(run);
      execute(executor);
    }
  }

  result.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  result.sim_time_s = to_seconds(ended_at);
  if (run.failed)
    result.outcome = RunOutcome::failed;
  else if (run.stopping() && !run.end_requested)
    result.outcome = RunOutcome::stopped;
  result.errors = run.errors();
  collect_stats(run, result);

  result.report = detail::run_description(graph, options);
  result.report["graph"]["hash"] = detail::graph_hash(graph);
  result.report.update({{"outcome", outcome_name(result.outcome)},
                        {"errors", result.errors},
                        {"ended_by", run.ended_by()},
                        {"run_time_s", result.sim_time_s},
                        {"wall_time_s", result.wall_time_s},
                        {"stats", stats_json(result)}});
  nlohmann::json metrics_meta = nlohmann::json::object();
  for (const auto& [path, meta] : run.report.metrics()) {
    nlohmann::json m = {{"unit", meta.unit}};
    if (meta.higher_is_better) m["higher_is_better"] = *meta.higher_is_better;
    if (meta.by_magnitude) m["by_magnitude"] = true;
    metrics_meta[path] = std::move(m);
  }
  result.report["metrics_meta"] = std::move(metrics_meta);
  nlohmann::json artifacts = nlohmann::json::array();
  for (const auto& a : run.report.artifacts())
    artifacts.push_back({{"file", a.file}, {"node", a.owner}, {"caption", a.caption}});
  result.report["artifacts"] = std::move(artifacts);
  const auto sections = run.report.sections();
  for (const auto& [key, section] : sections) {
    if (result.report.contains(key)) {
      result.errors.push_back("node '" + section.owner + "' reported section '" + key +
                              "', which is reserved by the runtime");
      continue;
    }
    result.report[key] = section.value;
  }
  if (!options.report_dir.empty()) detail::write_report(options.report_dir, result, sections);
  return result;
}

}  // namespace kestrel
