#pragma once
// Private: reads the top-level settings of a graph file into a GraphConfig.
#include "kestrel/runtime/graph.hpp"
#include "yaml_checks.hpp"

namespace kestrel {

/// Reads `kestrel`, `name`, `description`, `plugin_paths`, `executor` (with its default queue
/// policy), `clock`, `seed`, `duration` and `on_error` from the graph's root map.
void read_graph_header(const YAML::Node& root, YamlChecks& yaml, GraphConfig& g, QueuePolicy& default_policy);

}  // namespace kestrel
