#pragma once
// Private: orders a wired graph's nodes for the lockstep executor.
#include "kestrel/runtime/diagnostics.hpp"
#include "kestrel/runtime/graph.hpp"

namespace kestrel {

/// Fills g.topological_order: a topological order over the connections that are not delayed,
/// always taking the earliest-declared ready node. A cycle of undelayed connections is an error
/// that lists the cycle, located at its first connection.
void order_nodes(GraphConfig& g, Diagnostics& diag);

}  // namespace kestrel
