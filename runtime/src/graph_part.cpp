#include "graph_part.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>

#include "kestrel/registry.hpp"

namespace kestrel {

namespace {

template <typename T>
const T* find_named(const std::vector<T>& items, const std::string& name) {
  const auto it = std::find_if(items.begin(), items.end(), [&](const T& item) { return item.name == name; });
  return it == items.end() ? nullptr : &*it;
}

std::vector<std::string> names_of(const std::vector<PartPort>& ports) {
  std::vector<std::string> names;
  for (const auto& p : ports) names.push_back(p.name);
  return names;
}

// "node.name", one or a list, from `to` or `from`.
std::vector<PartBinding> read_bindings(const YAML::Node& n, const std::string& what, bool many, YamlChecks& yaml) {
  std::vector<PartBinding> out;
  if (!n) return out;
  std::vector<YAML::Node> items;
  if (n.IsSequence() && many)
    for (const auto& item : n) items.push_back(item);
  else
    items.push_back(n);
  for (const auto& item : items) {
    const auto text = yaml.scalar(item, what);
    if (!text) continue;
    const auto dot = text->find('.');
    if (dot == std::string::npos || dot == 0 || dot + 1 == text->size()) {
      yaml.error(item, fmt::format("{} must be node.name, not '{}'", what, *text));
      continue;
    }
    out.push_back({text->substr(0, dot), text->substr(dot + 1), item});
  }
  return out;
}

std::string optional_text(const YAML::Node& map, const char* key, YamlChecks& yaml) {
  const YAML::Node n = map[key];
  if (!n) return {};
  return yaml.scalar(n, fmt::format("'{}'", key)).value_or("");
}

// `inputs:` or `outputs:`: name -> node.port, or name -> {to|from: ..., type: ..., description: ...}.
std::vector<PartPort> read_ports(const YAML::Node& root, bool inputs, YamlChecks& yaml) {
  std::vector<PartPort> ports;
  const char* key = inputs ? "inputs" : "outputs";
  const char* bind = inputs ? "to" : "from";
  const YAML::Node map = root[key];
  if (!map) return ports;
  if (!map.IsMap()) {
    yaml.error(map, fmt::format("a part's '{}' must be a map of port name: {{{}: node.port}}", key, bind));
    return ports;
  }
  for (auto it = map.begin(); it != map.end(); ++it) {
    PartPort port;
    port.name = it->first.Scalar();
    port.yaml = it->first;
    if (!valid_node_id(port.name)) {
      yaml.error(it->first, fmt::format("a part's port name '{}' must start with a letter or '_' and hold only "
                                        "letters, digits, '_' and '-'",
                                        port.name));
      continue;
    }
    const YAML::Node value = it->second;
    if (value.IsMap()) {
      if (!yaml.keys(value, {bind, "type", "description"}, fmt::format("part port '{}'", port.name))) continue;
      port.bindings = read_bindings(value[bind], fmt::format("'{}'", bind), inputs, yaml);
      port.type = optional_text(value, "type", yaml);
      port.description = optional_text(value, "description", yaml);
      if (!value[bind])
        yaml.error(value, fmt::format("part port '{}' needs '{}': the node port it is", port.name, bind));
    } else {
      port.bindings = read_bindings(value, fmt::format("port '{}'", port.name), inputs, yaml);
    }
    if (find_named(ports, port.name)) {
      yaml.error(it->first, fmt::format("the part declares {} '{}' twice", inputs ? "input" : "output", port.name));
      continue;
    }
    if (!port.bindings.empty()) ports.push_back(std::move(port));
  }
  return ports;
}

std::vector<PartArg> read_args(const YAML::Node& root, YamlChecks& yaml) {
  std::vector<PartArg> args;
  const YAML::Node map = root["args"];
  if (!map) return args;
  if (!map.IsMap()) {
    yaml.error(map, "a part's 'args' must be a map of name: {default, unit, description, to: node.param}");
    return args;
  }
  for (auto it = map.begin(); it != map.end(); ++it) {
    PartArg arg;
    arg.name = it->first.Scalar();
    arg.yaml = it->first;
    const YAML::Node value = it->second;
    if (!value.IsMap()) {
      yaml.error(value,
                 fmt::format("arg '{}' must be a map: {{default, unit, description, to: node.param}}", arg.name));
      continue;
    }
    if (!yaml.keys(value, {"default", "unit", "description", "to"}, fmt::format("arg '{}'", arg.name))) continue;
    if (!value["to"]) {
      yaml.error(value, fmt::format("arg '{}' needs 'to': the parameters it sets (node.param, or a list)", arg.name));
      continue;
    }
    arg.bindings = read_bindings(value["to"], "'to'", true, yaml);
    if (const YAML::Node d = value["default"]) arg.default_value = d;
    arg.unit = optional_text(value, "unit", yaml);
    arg.description = optional_text(value, "description", yaml);
    if (find_named(args, arg.name)) {
      yaml.error(it->first, fmt::format("the part declares arg '{}' twice", arg.name));
      continue;
    }
    if (!arg.bindings.empty()) args.push_back(std::move(arg));
  }
  return args;
}

}  // namespace

const PartPort* PartInterface::input(const std::string& n) const { return find_named(inputs, n); }
const PartPort* PartInterface::output(const std::string& n) const { return find_named(outputs, n); }
const PartArg* PartInterface::arg(const std::string& n) const { return find_named(args, n); }

std::string PartInterface::ports() const {
  const auto list = [](const std::vector<PartPort>& p) { return p.empty() ? std::string("none") : join(names_of(p)); };
  return fmt::format("inputs: {}; outputs: {}", list(inputs), list(outputs));
}

std::vector<std::string> PartInterface::arg_names() const {
  std::vector<std::string> names;
  for (const auto& a : args) names.push_back(a.name);
  return names;
}

const std::vector<std::string>& part_file_keys() {
  static const std::vector<std::string> keys = {"kestrel", "part",   "description", "plugin_paths", "include",
                                                "args",    "inputs", "outputs",     "nodes",        "connections"};
  return keys;
}

bool is_part_file(const GraphSource::Impl& file) {
  const YAML::Node& root = file.root;
  return root.IsMap() && root["part"];
}

PartInterface read_part_interface(const GraphSource::Impl& file, YamlChecks& yaml) {
  PartInterface part;
  const YAML::Node& root = file.root;
  if (!root.IsMap()) return part;
  part.name = yaml.scalar(root["part"], "the part's name ('part:')").value_or("");
  part.description = optional_text(root, "description", yaml);
  part.inputs = read_ports(root, true, yaml);
  part.outputs = read_ports(root, false, yaml);
  part.args = read_args(root, yaml);
  return part;
}

std::optional<PartInfo> part_info(const GraphSource& source, const Registry& registry, Diagnostics& diagnostics) {
  const GraphSource::Impl& file = source.impl();
  diagnostics.append(file.read_errors);
  if (!is_part_file(file)) return std::nullopt;
  YamlChecks yaml(diagnostics, [&](const YAML::Node& n) { return file.at(n); });
  const PartInterface part = read_part_interface(file, yaml);
  // The part's own nodes' types, to tell the ports' message types.
  std::map<std::string, const NodeSpec*> specs;
  const YAML::Node& root = file.root;
  if (const YAML::Node nodes = root["nodes"]; nodes && nodes.IsSequence())
    for (const auto& n : nodes)
      if (n.IsMap() && n["id"] && n["type"] && n["id"].IsScalar() && n["type"].IsScalar())
        if (const NodeType* type = registry.find_node(n["type"].Scalar())) specs[n["id"].Scalar()] = &type->spec;
  const auto port_info = [&](const PartPort& p, bool output) {
    PartInfo::Port out{p.name, p.type, p.description, {}};
    for (const auto& b : p.bindings) {
      out.bound.push_back(b.node + "." + b.name);
      if (!out.type.empty()) continue;
      if (const auto it = specs.find(b.node); it != specs.end()) {
        const int index = output ? it->second->output_index(b.name) : it->second->input_index(b.name);
        if (index >= 0)
          out.type = output ? it->second->outputs()[static_cast<std::size_t>(index)].type()
                            : it->second->inputs()[static_cast<std::size_t>(index)].type();
      }
    }
    return out;
  };
  PartInfo info;
  info.name = part.name;
  info.description = part.description;
  for (const auto& p : part.inputs) info.inputs.push_back(port_info(p, false));
  for (const auto& p : part.outputs) info.outputs.push_back(port_info(p, true));
  for (const auto& a : part.args) {
    PartInfo::Arg arg{a.name, "", a.unit, a.description, {}};
    if (a.default_value) {
      YAML::Emitter text;
      text << YAML::Flow << a.default_value;
      arg.default_value = text.c_str();
    }
    for (const auto& b : a.bindings) arg.bound.push_back(b.node + "." + b.name);
    info.args.push_back(std::move(arg));
  }
  return info;
}

}  // namespace kestrel
