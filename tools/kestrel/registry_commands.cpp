// plugins and inspect: the commands that describe what the loaded plugins provide.
#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "commands.hpp"
#include "kestrel/runtime/diagnostics.hpp"
#include "kestrel/runtime/graph.hpp"
#include "kestrel/runtime/plugin_host.hpp"

namespace kestrel::cli {

namespace {

std::unique_ptr<PluginHost> load_plugins() {
  auto host = std::make_unique<PluginHost>();
  host->load_search_path();
  return host;
}

void print_errors(const PluginHost& host) {
  if (host.errors().empty()) return;
  std::fprintf(stderr, "\n%zu plugin file(s) refused:\n", host.errors().size());
  for (const auto& e : host.errors()) std::fprintf(stderr, "  %s\n", e.message.c_str());
}

std::string describe_param(const ParamSpec& p) {
  std::string type = p.type == ParamType::component ? "component<" + p.component_kind + ">" : to_string(p.type);
  std::string line = fmt::format("    {:<22} {:<22}", p.name, type);
  line += p.default_value ? fmt::format(" default {}", to_string(*p.default_value)) : std::string(" required");
  if (!p.unit.empty()) line += " " + p.unit;
  if (p.min || p.max)
    line += fmt::format("  range [{}, {}]", p.min ? fmt::format("{}", *p.min) : "-inf",
                        p.max ? fmt::format("{}", *p.max) : "inf");
  if (p.length) line += fmt::format("  {} values", *p.length);
  if (!p.allowed.empty()) line += fmt::format("  one of {{{}}}", fmt::join(p.allowed, ", "));
  line += "\n      " + p.description + "\n";
  return line;
}

void print_params(const ParamSet& set) {
  std::printf("\nParameters:\n");
  if (set.params.empty()) std::printf("    none\n");
  for (const auto& p : set.params) std::fputs(describe_param(p).c_str(), stdout);
  if (set.rules.empty()) return;
  std::printf("\nRules:\n");
  for (const auto& r : set.rules) std::printf("    %s\n", r.text.c_str());
}

void inspect_node(const NodeType& type, const Registry& registry) {
  const auto& spec = type.spec;
  std::printf("Node type %s\n  %s\n  plugin: %s\n", spec.type().c_str(), spec.summary().c_str(),
              type.plugin.empty() ? "(framework)" : type.plugin.c_str());
  if (!spec.details().empty()) std::printf("\n%s\n", spec.details().c_str());
  std::printf("\nInputs:\n");
  if (spec.inputs().empty()) std::printf("    none (a source)\n");
  for (const auto& p : spec.inputs())
    std::printf("    %-22s %-26s %s%s\n      %s\n", p.name.c_str(), p.type().c_str(),
                p.trigger == Trigger::on_message ? "triggers" : "latest value", p.optional ? ", optional" : "",
                p.description.c_str());
  std::printf("\nOutputs:\n");
  if (spec.outputs().empty()) std::printf("    none (a sink)\n");
  for (const auto& p : spec.outputs())
    std::printf("    %-22s %-26s\n      %s\n", p.name.c_str(), p.type().c_str(), p.description.c_str());
  print_params(spec.param_set());
  for (const auto& p : spec.params()) {
    if (p.type != ParamType::component) continue;
    std::printf("\n  '%s' accepts these %s components: %s\n", p.name.c_str(), p.component_kind.c_str(),
                fmt::format("{}", fmt::join(registry.component_names(p.component_kind), ", ")).c_str());
  }
}

// A message type and its fields: name, type, unit and frame in aligned columns, then what each is.
void print_message(const MessageTypeEntry& message) {
  const MessageInfo& info = message.info;
  std::printf("Message type %s\n  %s\n  first registered by: %s\n", info.name.c_str(), info.description.c_str(),
              message.plugin.empty() ? "(framework)" : message.plugin.c_str());
  if (info.fields.empty()) {
    std::printf("  fields: not declared (KESTREL_MESSAGE_FIELDS)\n");
    return;
  }
  std::size_t name_w = 5, type_w = 4, unit_w = 4;
  for (const auto& f : info.fields) {
    name_w = std::max(name_w, f.name.size());
    type_w = std::max(type_w, f.type.size());
    unit_w = std::max(unit_w, f.unit.size());
  }
  std::printf("  fields:\n    %-*s  %-*s  %-*s  %s\n", int(name_w), "field", int(type_w), "type", int(unit_w), "unit",
              "frame");
  for (const auto& f : info.fields)
    std::printf("    %-*s  %-*s  %-*s  %s\n      %s\n", int(name_w), f.name.c_str(), int(type_w), f.type.c_str(),
                int(unit_w), f.unit.empty() ? "-" : f.unit.c_str(), f.frame.empty() ? "-" : f.frame.c_str(),
                f.description.c_str());
}

// A part's interface: its ports, each with the node ports it is, and its args, each with the
// parameters it sets.
int inspect_part(const std::filesystem::path& file, const Registry& registry) {
  const GraphSource source = GraphSource::from_file(file);
  Diagnostics diagnostics;
  const auto part = part_info(source, registry, diagnostics);
  if (diagnostics.has_errors()) {
    std::fputs(diagnostics.str().c_str(), stderr);
    return kInvalidGraph;
  }
  if (!part) {
    std::fprintf(stderr, "%s is a runnable graph, not a part: `kestrel validate` or `kestrel dot` it\n",
                 file.string().c_str());
    return kUsage;
  }
  std::printf("Part %s (%s)\n", part->name.c_str(), file.string().c_str());
  if (!part->description.empty()) std::printf("  %s\n", part->description.c_str());
  const auto ports = [](const char* title, const std::vector<PartInfo::Port>& list) {
    std::printf("\n%s:\n", title);
    if (list.empty()) std::printf("    none\n");
    for (const auto& p : list)
      std::printf("    %-22s %-26s %s\n%s", p.name.c_str(), p.type.empty() ? "-" : p.type.c_str(),
                  fmt::format("{}", fmt::join(p.bound, ", ")).c_str(),
                  p.description.empty() ? "" : fmt::format("      {}\n", p.description).c_str());
  };
  ports("Inputs", part->inputs);
  ports("Outputs", part->outputs);
  std::printf("\nArgs:\n");
  if (part->args.empty()) std::printf("    none\n");
  for (const auto& a : part->args)
    std::printf("    %-22s %-26s sets %s\n%s", a.name.c_str(),
                (a.default_value.empty() ? std::string("(required)")
                                         : "default " + a.default_value + (a.unit.empty() ? "" : " " + a.unit))
                    .c_str(),
                fmt::format("{}", fmt::join(a.bound, ", ")).c_str(),
                a.description.empty() ? "" : fmt::format("      {}\n", a.description).c_str());
  return kOk;
}

}  // namespace

int plugins_command() {
  auto host = load_plugins();
  const Registry& registry = host->registry();
  for (const auto& plugin : host->plugins()) {
    std::printf("%s %s  (%s)\n  %s\n", plugin.name.c_str(), plugin.version.c_str(), plugin.file.string().c_str(),
                plugin.description.c_str());
    for (const auto& type : plugin.node_types)
      std::printf("    node       %-24s %s\n", type.c_str(), registry.find_node(type)->spec.summary().c_str());
    for (const auto& key : plugin.components)
      std::printf("    component  %-24s %s\n", key.c_str(),
                  registry.components().find(key)->second.spec.summary().c_str());
    for (const auto& m : plugin.messages)
      std::printf("    message    %-24s %s\n", m.c_str(), registry.find_message(m)->info.description.c_str());
  }
  if (host->plugins().empty()) {
    std::string path;
    for (const auto& dir : PluginHost::search_path()) {
      if (!path.empty()) path += ':';
      path += dir.string();
    }
    std::printf("no plugins found in: %s\n", path.c_str());
  }
  print_errors(*host);
  return host->errors().empty() ? kOk : kNotFound;
}

int inspect_command(const std::string& name) {
  auto host = load_plugins();
  const Registry& registry = host->registry();
  // A YAML file: a part's interface.
  std::error_code ec;
  if ((name.ends_with(".yaml") || name.ends_with(".yml")) && std::filesystem::is_regular_file(name, ec))
    return inspect_part(name, registry);
  if (const NodeType* type = registry.find_node(name)) {
    inspect_node(*type, registry);
    return kOk;
  }
  std::vector<const ComponentType*> matches;
  for (const auto& [key, c] : registry.components())
    if (key == name || c.spec.name() == name) matches.push_back(&c);
  if (matches.size() == 1) {
    const ComponentType& c = *matches.front();
    std::printf("Component %s/%s\n  %s\n  plugin: %s\n", c.kind.c_str(), c.spec.name().c_str(),
                c.spec.summary().c_str(), c.plugin.c_str());
    if (!c.spec.details().empty()) std::printf("\n%s\n", c.spec.details().c_str());
    print_params(c.spec.param_set());
    return kOk;
  }
  if (matches.size() > 1) {
    std::fprintf(stderr, "'%s' names several components; say which: ", name.c_str());
    for (const auto* c : matches) std::fprintf(stderr, "%s/%s ", c->kind.c_str(), c->spec.name().c_str());
    std::fprintf(stderr, "\n");
    return kNotFound;
  }
  // A message type by its full name (kestrel.Detections) or by its last part (Detections).
  const MessageTypeEntry* message = registry.find_message(name);
  for (const auto& [full, m] : registry.messages())
    if (!message && full.size() > name.size() && full.ends_with("." + name)) message = &m;
  if (message) {
    print_message(*message);
    return kOk;
  }
  std::vector<std::string> names = registry.node_type_names();
  for (const auto& [key, c] : registry.components()) names.push_back(c.spec.name());
  const std::string near = nearest_name(name, names);
  std::fprintf(stderr, "no node type, component or message type named '%s'%s\n", name.c_str(),
               near.empty() ? "" : fmt::format(" (did you mean '{}'?)", near).c_str());
  print_errors(*host);
  return kNotFound;
}

}  // namespace kestrel::cli
