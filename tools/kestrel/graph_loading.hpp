#pragma once
// Reading and validating a graph, the same way for every subcommand that takes one, so that an
// invalid graph ends each of them with the same message and exit code.
#include <memory>
#include <optional>

#include "commands.hpp"
#include "kestrel/runtime/graph.hpp"
#include "kestrel/runtime/plugin_host.hpp"

namespace kestrel::cli {

struct LoadedGraph {
  std::unique_ptr<PluginHost> plugins;  ///< keeps the graph's plugins loaded
  std::optional<GraphConfig> graph;     ///< unset if the graph is invalid
};

/// Reads the graph, loads the plugins it may need, validates it with the overrides. Prints every
/// problem, each with file:line:col, and what was not done because of them ("the graph was not
/// run").
LoadedGraph load_graph(const GraphArgs& args, const char* not_done = "the graph was not run");

}  // namespace kestrel::cli
