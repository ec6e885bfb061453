#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "kestrel/runtime/graph.hpp"

namespace kestrel {

namespace {

// The namespace of a node of a part ("front/inner" for "front/inner/depth"; "" for the graph's own).
std::string namespace_of(const std::string& id) {
  const auto slash = id.rfind('/');
  return slash == std::string::npos ? std::string() : id.substr(0, slash);
}

std::string node_record(const NodeConfig& node) {
  const auto& spec = node.type->spec;
  std::vector<std::string> inputs, outputs;
  for (const auto& p : spec.inputs()) inputs.push_back(fmt::format("<in_{0}> {0}", p.name));
  for (const auto& p : spec.outputs()) outputs.push_back(fmt::format("<out_{0}> {0}", p.name));
  const auto slash = node.id.rfind('/');
  const std::string name = slash == std::string::npos ? node.id : node.id.substr(slash + 1);
  return fmt::format("\"{}\" [label=\"{{{{{}}}|{}\\n({})|{{{}}}}}\"];\n", node.id, fmt::join(inputs, "|"), name,
                     spec.type(), fmt::join(outputs, "|"));
}

// The nodes of namespace `ns` and, nested in it, a cluster for each part it includes.
void emit_namespace(const GraphConfig& graph, const std::string& ns, const std::string& indent, std::string& dot) {
  for (const auto& node : graph.nodes)
    if (namespace_of(node.id) == ns) dot += indent + node_record(node);
  std::vector<std::string> inner;
  for (const auto& node : graph.nodes) {
    const std::string of = namespace_of(node.id);
    if (of.size() <= ns.size() || (!ns.empty() && of.rfind(ns + "/", 0) != 0)) continue;
    const auto start = ns.empty() ? 0 : ns.size() + 1;
    const std::string child = of.substr(0, of.find('/', start));
    if (std::find(inner.begin(), inner.end(), child) == inner.end()) inner.push_back(child);
  }
  for (const auto& child : inner) {
    dot += fmt::format("{}subgraph \"cluster_{}\" {{\n{}  label=\"{}\"; style=rounded; color=gray50;\n", indent, child,
                       indent, child.substr(child.rfind('/') + 1));
    emit_namespace(graph, child, indent + "  ", dot);
    dot += indent + "}\n";
  }
}

}  // namespace

std::string to_dot(const GraphConfig& graph) {
  std::string dot = fmt::format("digraph \"{}\" {{\n  rankdir=LR;\n  node [shape=record, fontname=\"Helvetica\"];\n",
                                graph.name.empty() ? "kestrel" : graph.name);
  // Each part is a cluster, named by its namespace.
  emit_namespace(graph, "", "  ", dot);
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
