#pragma once
// The in-tree plugins, loaded once per test program from the build's plugin folder. The host is
// never destroyed: plugins are never unloaded, and nodes they made may outlive a test.
#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <vector>

#include "kestrel/runtime/graph.hpp"
#include "kestrel/runtime/plugin_host.hpp"
#include "kestrel/runtime/run.hpp"

namespace kestrel::testing {

inline PluginHost& built_plugins() {
  static PluginHost* host = [] {
    auto* h = new PluginHost();
    h->load_search_path();
    return h;
  }();
  return *host;
}

/// Builds `source` with the in-tree plugins and `overrides` (as --set gives them) and runs it for
/// `seconds`; a graph that does not build fails the test and gives an empty result.
inline RunResult run_built_graph(const GraphSource& source, double seconds,
                                 const std::vector<std::string>& overrides = {},
                                 std::optional<std::uint64_t> seed = {}) {
  auto& registry = built_plugins().registry();
  auto built = build_graph(source, registry, overrides);
  EXPECT_TRUE(built.graph) << built.diagnostics.str();
  if (!built.graph) return {};
  RunOptions options;
  options.duration_s = seconds;
  options.seed = seed;
  return run_graph(*built.graph, registry, options);
}

}  // namespace kestrel::testing
