#pragma once
// One-line graph building and running on the test nodes, for the runtime's tests.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "kestrel/runtime/graph.hpp"
#include "kestrel/runtime/plugin_host.hpp"
#include "kestrel/runtime/run.hpp"
#include "kestrel/testing/plugins.hpp"

namespace kestrel::testing {

inline BuildResult build(const std::string& yaml, const std::vector<std::string>& overrides = {}) {
  return build_graph(GraphSource::from_string(yaml, "g.yaml"), test_plugins().registry(), overrides);
}

/// Builds and runs; fails the test if the graph is invalid.
inline RunResult run(const std::string& yaml, RunOptions options = {}) {
  auto built = build(yaml);
  EXPECT_TRUE(built.graph) << built.diagnostics.str();
  if (!built.graph) return {};
  return run_graph(*built.graph, test_plugins().registry(), options);
}

inline const NodeStats& node_stats(const RunResult& r, const std::string& id) {
  for (const auto& n : r.nodes)
    if (n.id == id) return n;
  throw std::runtime_error("no node " + id);
}

inline const ConnectionStats& connection_stats(const RunResult& r, const std::string& label) {
  for (const auto& c : r.connections)
    if (c.label == label) return c;
  throw std::runtime_error("no connection " + label);
}

/// The diagnostics as "line:col: message" lines without the file name, for compact asserts.
inline std::vector<std::string> messages(const BuildResult& r) {
  std::vector<std::string> out;
  for (const auto& d : r.diagnostics.items()) out.push_back(d.str());
  return out;
}

}  // namespace kestrel::testing
