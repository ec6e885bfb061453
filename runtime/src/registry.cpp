#include "kestrel/registry.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace kestrel {

namespace {
std::string origin(const std::string& plugin) { return plugin.empty() ? "the framework" : plugin; }
}  // namespace

Registry::Registry() { add_message<AnyMessage>(); }

namespace {
void check_spec(const std::string& what, const ParamSet& params) {
  const auto problems = check_param_set(params);
  if (!problems.empty()) throw Error(fmt::format("{} has a malformed spec: {}", what, fmt::join(problems, "; ")));
}
}  // namespace

void Registry::add_node(NodeSpec spec, NodeFactory factory) {
  const std::string type = spec.type();
  if (auto it = nodes_.find(type); it != nodes_.end())
    throw Error("node type '" + type + "' is registered twice: by " + origin(it->second.plugin) + " and by " +
                origin(current_plugin_));
  if (spec.summary().empty()) throw Error("node type '" + type + "' has a malformed spec: no summary");
  check_spec("node type '" + type + "'", spec.param_set());
  for (const auto& port : spec.inputs()) {
    if (!port.tap) continue;
    const ParamSpec* topics = spec.find_param(port.tap->topics_param);
    if (!topics || topics->type != ParamType::string)
      throw Error("node type '" + type + "' has a malformed spec: tap '" + port.name + "' names '" +
                  port.tap->topics_param + "', which is not a string parameter");
  }
  for (const auto* ports : {&spec.inputs(), &spec.outputs()})
    for (const auto& port : *ports) add_message(port.message);
  nodes_.emplace(type, NodeType{std::move(spec), std::move(factory), current_plugin_});
}

void Registry::add_component(std::string kind, ComponentSpec spec, ComponentFactory factory) {
  const std::string key = kind + "/" + spec.name();
  if (auto it = components_.find(key); it != components_.end())
    throw Error("component '" + key + "' is registered twice: by " + origin(it->second.plugin) + " and by " +
                origin(current_plugin_));
  if (spec.summary().empty()) throw Error("component '" + key + "' has a malformed spec: no summary");
  check_spec("component '" + key + "'", spec.param_set());
  components_.emplace(key, ComponentType{std::move(kind), std::move(spec), std::move(factory), current_plugin_});
}

void Registry::add_message(MessageInfo info) {
  const std::string name = info.name;
  messages_.try_emplace(name, MessageTypeEntry{std::move(info), current_plugin_});
}

const NodeType* Registry::find_node(std::string_view type) const {
  auto it = nodes_.find(type);
  return it == nodes_.end() ? nullptr : &it->second;
}

const ComponentType* Registry::find_component(std::string_view kind, std::string_view name) const {
  std::string key(kind);
  key += "/";
  key += name;
  auto it = components_.find(key);
  return it == components_.end() ? nullptr : &it->second;
}

const MessageTypeEntry* Registry::find_message(std::string_view name) const {
  auto it = messages_.find(name);
  return it == messages_.end() ? nullptr : &it->second;
}

std::vector<std::string> Registry::node_type_names() const {
  std::vector<std::string> names;
  for (const auto& [name, _] : nodes_) names.push_back(name);
  return names;
}

std::vector<std::string> Registry::component_names(std::string_view kind) const {
  std::vector<std::string> names;
  for (const auto& [_, c] : components_)
    if (c.kind == kind) names.push_back(c.spec.name());
  return names;
}

}  // namespace kestrel
