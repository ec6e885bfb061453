#include <fmt/format.h>

#include "kestrel/runtime/graph.hpp"

namespace kestrel {

std::string to_dot(const GraphConfig& graph) {
  std::string dot = fmt::format("digraph \"{}\" {{\n  rankdir=LR;\n  node [shape=record, fontname=\"Helvetica\"];\n",
                                graph.name.empty() ? "kestrel" : graph.name);
  for (const auto& node : graph.nodes) {
    const auto& spec = node.type->spec;
    std::vector<std::string> inputs, outputs;
    for (const auto& p : spec.inputs()) inputs.push_back(fmt::format("<in_{0}> {0}", p.name));
    for (const auto& p : spec.outputs()) outputs.push_back(fmt::format("<out_{0}> {0}", p.name));
    dot += fmt::format("  \"{}\" [label=\"{{{{{}}}|{}\\n({})|{{{}}}}}\"];\n", node.id, fmt::join(inputs, "|"), node.id,
                       spec.type(), fmt::join(outputs, "|"));
  }
  for (const auto& c : graph.connections) {
    const auto& from = graph.nodes[static_cast<std::size_t>(c.from_node)];
    const auto& to = graph.nodes[static_cast<std::size_t>(c.to_node)];
    const auto& out = from.type->spec.outputs()[static_cast<std::size_t>(c.from_port)];
    const auto& in = to.type->spec.inputs()[static_cast<std::size_t>(c.to_port)];
    std::string label = graph.executor == ExecutorKind::realtime ? c.policy.str() : "";
    dot += fmt::format("  \"{}\":out_{} -> \"{}\":in_{} [label=\"{}\"{}];\n", from.id, out.name, to.id, in.name,
                       c.delayed ? (label.empty() ? "delayed" : label + ", delayed") : label,
                       c.delayed ? ", style=dashed, constraint=false" : "");
  }
  dot += "}\n";
  return dot;
}

}  // namespace kestrel
