// The order in which the lockstep executor steps the nodes, and the cycles that forbid one.
#include "graph_order.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

namespace kestrel {

void order_nodes(GraphConfig& g_, Diagnostics& diag_) {
  const std::size_t n = g_.nodes.size();
  std::vector<int> indegree(n, 0);
  std::vector<std::vector<const ConnectionConfig*>> out(n);
  for (const auto& c : g_.connections) {
    if (c.delayed) continue;
    ++indegree[static_cast<std::size_t>(c.to_node)];
    out[static_cast<std::size_t>(c.from_node)].push_back(&c);
  }
  // Kahn's algorithm, always taking the earliest-declared ready node: a stable, documented order.
  std::vector<bool> done(n, false);
  for (std::size_t step = 0; step < n; ++step) {
    std::size_t next = n;
    for (std::size_t i = 0; i < n && next == n; ++i)
      if (!done[i] && indegree[i] == 0) next = i;
    if (next == n) break;
    done[next] = true;
    g_.topological_order.push_back(static_cast<int>(next));
    for (const auto* c : out[next]) --indegree[static_cast<std::size_t>(c->to_node)];
  }
  if (g_.topological_order.size() == n) return;

  // Walk back along non-delayed connections from a blocked node until a node repeats: a cycle.
  std::vector<const ConnectionConfig*> into(n, nullptr);
  for (const auto& c : g_.connections)
    if (!c.delayed && !done[static_cast<std::size_t>(c.from_node)] && !done[static_cast<std::size_t>(c.to_node)])
      into[static_cast<std::size_t>(c.to_node)] = &c;
  std::size_t node = 0;
  while (done[node]) ++node;
  std::vector<int> seen_at(n, -1);
  std::vector<const ConnectionConfig*> path;
  while (seen_at[node] < 0) {
    seen_at[node] = static_cast<int>(path.size());
    path.push_back(into[node]);
    node = static_cast<std::size_t>(into[node]->from_node);
  }
  std::vector<const ConnectionConfig*> cycle(path.begin() + seen_at[node], path.end());
  std::reverse(cycle.begin(), cycle.end());
  std::vector<std::string> labels;
  for (const auto* c : cycle) labels.push_back(c->label);
  const auto first =
      *std::min_element(cycle.begin(), cycle.end(), [](auto* a, auto* b) { return a->where.line < b->where.line; });
  diag_.error(first->where, fmt::format("cycle not broken by a delayed connection: {}; mark one of these connections "
                                        "'delayed: true'",
                                        fmt::join(labels, ", ")));
}

}  // namespace kestrel
