#pragma once
// The plugins a test program loads: the in-tree plugins from the build's plugin folder, the test
// nodes (tests/support/test_nodes), or both. Each host is made once per program and never
// destroyed: plugins are never unloaded, and nodes they made may outlive a test. A plugin that
// does not load throws, which fails the test that asked for it with the host's message.
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "kestrel/runtime/graph.hpp"
#include "kestrel/runtime/plugin_host.hpp"
#include "kestrel/runtime/run.hpp"

namespace kestrel::testing {

namespace detail {

inline void load_test_nodes(PluginHost& host) {
  if (!host.load(KESTREL_TEST_PLUGIN_DIR "/kestrel_test_nodes.so"))
    throw std::runtime_error("the test nodes did not load: " + host.errors().back().message);
}

}  // namespace detail

/// The plugins that ship, found as `kestrel` finds them (KESTREL_PLUGIN_PATH, then the build's
/// plugin folder).
inline PluginHost& built_plugins() {
  static PluginHost* host = [] {
    auto* h = new PluginHost();
    h->load_search_path();
    return h;
  }();
  return *host;
}

/// The test nodes only: counters, relays, faulty nodes, collectors, a known scene.
inline PluginHost& test_plugins() {
  static PluginHost* host = [] {
    auto* h = new PluginHost();
    detail::load_test_nodes(*h);
    return h;
  }();
  return *host;
}

/// The plugins that ship and the test nodes, in one registry.
inline PluginHost& built_and_test_plugins() {
  static PluginHost* host = [] {
    auto* h = new PluginHost();
    h->load_search_path();
    detail::load_test_nodes(*h);
    return h;
  }();
  return *host;
}

/// Builds `source` with `plugins` and `overrides` (as --set gives them) and runs it for
/// `seconds` (the graph's own duration when unset) with `seed`. A graph that does not build
/// throws with its diagnostics.
inline RunResult run_graph_with(PluginHost& plugins, const GraphSource& source, std::optional<double> seconds = {},
                                const std::vector<std::string>& overrides = {},
                                std::optional<std::uint64_t> seed = {}) {
  auto built = build_graph(source, plugins.registry(), overrides);
  if (!built.graph) throw std::runtime_error("the graph does not build:\n" + built.diagnostics.str());
  RunOptions options;
  options.duration_s = seconds;
  options.seed = seed;
  return run_graph(*built.graph, plugins.registry(), options);
}

/// run_graph_with() on the plugins that ship.
inline RunResult run_built_graph(const GraphSource& source, std::optional<double> seconds = {},
                                 const std::vector<std::string>& overrides = {},
                                 std::optional<std::uint64_t> seed = {}) {
  return run_graph_with(built_plugins(), source, seconds, overrides, seed);
}

}  // namespace kestrel::testing
