#include "graph_record.hpp"

#include <fmt/format.h>

#include "kestrel/params.hpp"
#include "kestrel/registry.hpp"
#include "kestrel/version.hpp"
#include "seeds.hpp"

namespace kestrel::detail {

nlohmann::json param_json(const ParamValue& value) {
  struct Visitor {
    nlohmann::json operator()(bool b) const { return b; }
    nlohmann::json operator()(std::int64_t i) const { return i; }
    nlohmann::json operator()(double d) const { return d; }
    nlohmann::json operator()(const std::string& s) const { return s; }
    nlohmann::json operator()(const std::vector<double>& l) const { return l; }
    nlohmann::json operator()(const ComponentConfig& c) const {
      nlohmann::json params = nlohmann::json::object();
      if (c.params)
        for (const auto& [k, v] : c.params->values()) params[k] = param_json(v);
      return {{"type", c.type}, {"params", params}};
    }
  };
  return std::visit(Visitor{}, value);
}

nlohmann::json resolved_graph_json(const GraphConfig& graph) {
  nlohmann::json nodes = nlohmann::json::object();
  for (const auto& n : graph.nodes) {
    nlohmann::json params = nlohmann::json::object();
    for (const auto& [k, v] : n.params.values()) params[k] = param_json(v);
    nodes[n.id] = {{"type", n.type ? n.type->spec.type() : std::string()}, {"params", params}};
  }
  nlohmann::json connections = nlohmann::json::array();
  for (const auto& c : graph.connections)
    connections.push_back({{"connection", c.label}, {"policy", c.policy.str()}, {"delayed", c.delayed}});
  return {{"nodes", nodes}, {"connections", connections}};
}

std::string graph_hash(const GraphConfig& graph) {
  nlohmann::json canonical = resolved_graph_json(graph);
  canonical["executor"] = graph.executor == ExecutorKind::lockstep ? "lockstep" : "realtime";
  canonical["clock"] = graph.clock == ClockKind::simulated ? "simulated" : "wall";
  canonical["real_time_factor"] = graph.real_time_factor;
  const std::string text = canonical.dump();  // object keys are sorted: the dump is canonical
  return fmt::format("fnv1a64:{:016x}", fnv1a64(text));
}

}  // namespace kestrel::detail

namespace kestrel::detail {

nlohmann::json run_description(const GraphConfig& graph, const RunOptions& options) {
  const auto duration = options.duration_s ? options.duration_s : graph.duration_s;
  return {{"kestrel_version", KESTREL_VERSION_STRING},
          {"graph",
           {{"file", graph.file.string()},
            {"name", graph.name},
            {"executor", graph.executor == ExecutorKind::lockstep ? "lockstep" : "realtime"},
            {"clock", graph.clock == ClockKind::simulated ? "simulated" : "wall"},
            {"seed", options.seed.value_or(graph.seed)},
            {"duration_s", duration ? nlohmann::json(*duration) : nlohmann::json(nullptr)},
            {"resolved", resolved_graph_json(graph)}}}};
}

}  // namespace kestrel::detail
