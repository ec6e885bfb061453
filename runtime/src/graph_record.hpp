#pragma once
// Private: the resolved graph as report.json records it, so that a report says exactly what ran.
#include <nlohmann/json.hpp>
#include <string>

#include "kestrel/runtime/graph.hpp"
#include "kestrel/runtime/run.hpp"

namespace kestrel::detail {

/// A parameter value as JSON: numbers, strings and lists as such; a component as
/// {"type": NAME, "params": {...}}.
nlohmann::json param_json(const ParamValue& value);

/// Every node with its type and resolved parameters (defaults, includes and --set applied), and
/// every connection with its policy.
nlohmann::json resolved_graph_json(const GraphConfig& graph);

/// "fnv1a64:<16 hex digits>" of the resolved graph's canonical JSON with the executor and clock:
/// equal for two runs of the same graph with the same settings, whatever the files looked like.
std::string graph_hash(const GraphConfig& graph);

/// {"kestrel_version", "graph": {"file", "name", "executor", "clock", "seed", "duration_s",
/// "resolved"}}: what runs, as report.json and Context::run_description() give it.
nlohmann::json run_description(const GraphConfig& graph, const RunOptions& options);

}  // namespace kestrel::detail
