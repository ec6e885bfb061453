// Validates a graph's YAML against the registry and builds a GraphConfig: the graph's header,
// its nodes and the connections between them. Parameters are checked by ParamChecker, overrides
// parsed in param_overrides.cpp and the node order found in graph_order.cpp. Every problem is
// collected (not thrown) with its file:line:col, so that `kestrel validate` reports them all in
// one pass.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <sstream>

#include "graph_header.hpp"
#include "graph_order.hpp"
#include "graph_part.hpp"
#include "graph_source.hpp"
#include "param_checker.hpp"
#include "param_overrides.hpp"
#include "tap_selection.hpp"
#include "yaml_checks.hpp"

namespace kestrel {

namespace {

const std::vector<std::string> kTopLevelKeys = {"kestrel",  "name",     "description", "plugin_paths",
                                                "include",  "executor", "clock",       "seed",
                                                "duration", "on_error", "nodes",       "connections"};
const std::vector<std::string> kNodeKeys = {"id", "type", "params", "description"};
const std::vector<std::string> kConnectionKeys = {"from", "to", "policy", "delayed"};

class Builder {
 public:
  Builder(const GraphSource::Impl& src, const Registry& registry)
      : src_(src),
        cur_(&src),
        registry_(registry),
        yaml_(diag_, [this](const YAML::Node& n) { return cur_->at(n); }),
        params_(diag_, yaml_, registry) {}

  BuildResult build(const std::vector<std::string>& overrides, const std::vector<const GraphSource*>& fragments,
                    std::optional<ExecutorKind> executor);

 private:
  SourceLocation at(const YAML::Node& n) const { return cur_->at(n); }
  // Where an earlier definition is, as seen from the file being read: "line N" in the same file.
  std::string earlier(const SourceLocation& where) const {
    return where.file == cur_->label ? fmt::format("line {}", where.line) : where.str();
  }
  void error(const YAML::Node& n, std::string message) { diag_.error(at(n), std::move(message)); }
  bool check_keys(const YAML::Node& map, const std::vector<std::string>& allowed, const std::string& what) {
    return yaml_.keys(map, allowed, what);
  }
  std::optional<std::string> scalar(const YAML::Node& n, const std::string& what) { return yaml_.scalar(n, what); }
  std::optional<double> number(const YAML::Node& n, const std::string& what) { return yaml_.number(n, what); }

  void read_fragments();
  void check_overrides_name_nodes();
  void read_nodes();
  void read_connections();
  void connect_taps();
  void check_inputs_connected();
  void check_executor_needs(bool executor_from_command_line);

  struct Endpoint {
    int node = -1;
    int port = -1;
  };
  // A namespace: the graph's own, or a part's (graph_part.hpp). Files included with `file:` share
  // their includer's.
  struct Scope {
    std::string prefix;                            // "" for the graph; "front/" in part 'front'
    const GraphSource::Impl* part_file = nullptr;  // the part's file; null for the graph
    const GraphSource::Impl* includer = nullptr;   // the file that included it
    const GraphSource::Impl::Include* include = nullptr;
    PartInterface part;
    std::map<std::string, Scope*> parts;  // the parts included in it, by namespace
    // Each declared port, resolved to its nodes' ports (empty where its binding is broken).
    std::map<std::string, std::vector<Endpoint>> inputs, outputs;
    std::string name() const { return prefix.empty() ? prefix : prefix.substr(0, prefix.size() - 1); }
    std::string describe() const { return fmt::format("part '{}' ({})", name(), part_file->label); }
  };
  struct FileInScope {
    const GraphSource::Impl* file;
    Scope* scope;
  };
  void collect(const GraphSource::Impl& file, Scope& scope);
  void resolve_part_ports(Scope& scope);
  void apply_part_args(Scope& scope, const std::map<std::string, Override>& given);
  void check_part_arg_bindings(const Scope& scope);
  std::vector<Endpoint> endpoint(const YAML::Node& n, bool output);
  std::vector<Endpoint> resolve(const Scope& scope, const std::string& node, const std::string& port, bool output,
                                const YAML::Node& n);

  const GraphSource::Impl& src_;
  const GraphSource::Impl* cur_;                // the file being read: the graph or one it includes
  std::vector<FileInScope> files_;              // included files depth-first, then the graph itself
  std::vector<std::unique_ptr<Scope>> scopes_;  // the graph's first
  Scope* scope_ = nullptr;                      // the scope of the file being read
  std::set<std::string> arg_override_nodes_;    // nodes an arg sets (their binding is checked as such)
  const Registry& registry_;
  Diagnostics diag_;
  YamlChecks yaml_;
  ParamChecker params_;
  GraphConfig g_;
  QueuePolicy default_policy_;
  std::map<std::string, int> node_index_;
  Overrides overrides_;
  std::vector<bool> node_ok_;               // type known (ports can be checked)
  std::vector<SourceLocation> type_where_;  // each node's `type:`
  // Inputs named by a connection that failed for another reason: not also "not connected".
  std::set<std::pair<int, int>> attempted_inputs_;
  std::set<int> nodes_with_broken_inputs_;
  std::map<std::pair<int, int>, SourceLocation> input_taken_;  // (node, input) -> its connection
  std::set<std::array<int, 4>> tapped_;                        // (tap node, tap input, node, output)
};

// `file` and what it includes, depth-first, each in its scope: a file's nodes join its includer's
// scope; a part's take a namespace of its own, nested in its includer's.
void Builder::collect(const GraphSource::Impl& file, Scope& scope) {
  for (const auto& include : file.includes) {
    const GraphSource::Impl& child = *include.source;
    cur_ = &file;
    if (include.part()) {
      const YAML::Node part_node = include.entry["part"];
      if (!is_part_file(child)) {
        error(part_node, fmt::format("'{}' is a runnable graph, not a part (a part's file starts with 'part:'); a part "
                                     "never includes a runnable graph",
                                     part_node.Scalar()));
        continue;
      }
      if (scope.parts.count(include.as)) {
        error(include.entry["as"],
              fmt::format("two parts are included as '{}': each needs a namespace of its own", include.as));
        continue;
      }
      auto inner = std::make_unique<Scope>();
      inner->prefix = scope.prefix + include.as + "/";
      inner->part_file = &child;
      inner->includer = &file;
      inner->include = &include;
      cur_ = &child;
      if (!check_keys(child.root, part_file_keys(), "a part")) continue;
      inner->part = read_part_interface(child, yaml_);
      scope.parts[include.as] = inner.get();
      Scope& next = *inner;
      scopes_.push_back(std::move(inner));
      collect(child, next);
      continue;
    }
    if (scope.part_file) {
      error(include.entry,
            "a part includes only parts (with 'part:' and 'as:'), never a file whose nodes would join "
            "its own");
      continue;
    }
    if (is_part_file(child)) {
      error(include.entry, "this file is a part: include it with 'part:' and 'as:', and connect to its ports");
      continue;
    }
    cur_ = &child;
    if (!child.root.IsMap()) {
      diag_.error(at(child.root), "an included graph file must be a YAML map with 'nodes' and 'connections'");
      continue;
    }
    if (check_keys(child.root, kTopLevelKeys, "the included graph")) collect(child, scope);
  }
  cur_ = &src_;
  files_.push_back({&file, &scope});
}

// Every file's nodes, then every file's connections, so that a graph can connect to the nodes of
// the graphs it includes.
void Builder::read_fragments() {
  bool any_nodes = false;
  for (const auto& [file, scope] : files_) {
    cur_ = file;
    scope_ = scope;
    const YAML::Node& root = file->root;
    if (root["nodes"]) any_nodes = true;
    read_nodes();
  }
  cur_ = &src_;
  scope_ = scopes_.front().get();
  if (!any_nodes) diag_.error(at(src_.root), "the graph has no 'nodes' list");
  resolve_part_ports(*scopes_.front());
  check_part_arg_bindings(*scopes_.front());
  for (const auto& [file, scope] : files_) {
    cur_ = file;
    scope_ = scope;
    read_connections();
  }
  cur_ = &src_;
  scope_ = scopes_.front().get();
}

void Builder::read_nodes() {
  const YAML::Node& root = cur_->root;
  const YAML::Node nodes = root["nodes"];
  if (!nodes) return;
  if (!nodes.IsSequence()) {
    error(nodes, "'nodes' must be a list");
    return;
  }
  const auto known_types = registry_.node_type_names();
  for (const auto& n : nodes) {
    if (!check_keys(n, kNodeKeys, "a node")) continue;
    NodeConfig config;
    config.where = at(n);
    const YAML::Node id = n["id"];
    const YAML::Node type = n["type"];
    if (!id) error(n, "node without an 'id'");
    if (!type) error(n, "node without a 'type'");
    if (!id || !type) continue;
    auto id_text = scalar(id, "a node id");
    auto type_text = scalar(type, "a node type");
    if (!id_text || !type_text) continue;
    if (!valid_node_id(*id_text)) {
      error(id, fmt::format("node id '{}' must start with a letter or '_' and hold only letters, digits, '_' and '-'",
                            *id_text));
      continue;
    }
    if (scope_->parts.count(*id_text)) {
      error(id, fmt::format("node id '{}' is also the namespace of an included part", *id_text));
      continue;
    }
    config.id = scope_->prefix + *id_text;
    if (auto prior = node_index_.find(config.id); prior != node_index_.end()) {
      error(id, fmt::format("duplicate node id '{}' (first defined at {})", config.id,
                            earlier(g_.nodes[static_cast<std::size_t>(prior->second)].where)));
      continue;
    }
    config.type = registry_.find_node(*type_text);
    if (!config.type) {
      error(type,
            fmt::format("unknown node type '{}'{}; known types: {}", *type_text, did_you_mean(*type_text, known_types),
                        known_types.empty() ? "none (no plugin loaded)" : join(known_types)));
    } else {
      const std::string owner = fmt::format("node '{}' ({})", config.id, config.type->spec.type());
      const auto ov = overrides_.find(config.id);
      auto params = params_.check(n["params"], config.type->spec.param_set(), owner, config.where,
                                  ov == overrides_.end() ? nullptr : &ov->second);
      if (params) config.params = std::move(*params);
    }
    node_index_[config.id] = static_cast<int>(g_.nodes.size());
    node_ok_.push_back(config.type != nullptr);
    type_where_.push_back(at(type));
    g_.nodes.push_back(std::move(config));
  }
}

void Builder::check_overrides_name_nodes() {
  for (const auto& [node, params] : overrides_) {
    if (node_index_.count(node) || arg_override_nodes_.count(node)) continue;
    for (const auto& [_, o] : params)
      diag_.error(o.where, fmt::format("no node '{}' in the graph{}", node, did_you_mean(node, [&] {
                                         std::vector<std::string> ids;
                                         for (const auto& [k, _] : node_index_) ids.push_back(k);
                                         return ids;
                                       }())));
  }
}

std::vector<Builder::Endpoint> Builder::endpoint(const YAML::Node& n, bool output) {
  auto text = scalar(n, output ? "'from'" : "'to'");
  if (!text) return {};
  const auto dot = text->find('.');
  if (dot == std::string::npos || dot == 0 || dot + 1 == text->size()) {
    error(n, fmt::format("'{}' must be node.port", *text));
    return {};
  }
  return resolve(*scope_, text->substr(0, dot), text->substr(dot + 1), output, n);
}

// `node.port` as written in `scope`: a node of its own, or a port its included part declares.
std::vector<Builder::Endpoint> Builder::resolve(const Scope& scope, const std::string& node, const std::string& port,
                                                bool output, const YAML::Node& n) {
  const char* direction = output ? "output" : "input";
  const std::string text = node + "." + port;
  if (const auto part = scope.parts.find(node); part != scope.parts.end()) {
    const Scope& inner = *part->second;
    const auto& declared = output ? inner.outputs : inner.inputs;
    const auto it = declared.find(port);
    if (it == declared.end()) {
      const auto& ports = output ? inner.part.outputs : inner.part.inputs;
      std::vector<std::string> names;
      for (const auto& p : ports) names.push_back(p.name);
      const bool other = output ? inner.part.input(port) != nullptr : inner.part.output(port) != nullptr;
      error(n, fmt::format("{} has no {} '{}'{}{}; its ports: {}", inner.describe(), direction, port,
                           did_you_mean(port, names),
                           other ? fmt::format("; '{}' is an {}, and connections go from an output to an input", text,
                                               output ? "input" : "output")
                                 : "",
                           inner.part.ports()));
      return {};
    }
    return it->second;  // empty where the part's binding is broken (reported in its file)
  }
  // A node inside an included part is reached only through the part's ports.
  if (const auto slash = node.find('/'); slash != std::string::npos) {
    if (const auto part = scope.parts.find(node.substr(0, slash)); part != scope.parts.end()) {
      // The input it meant is not also "not connected".
      if (const auto inside = node_index_.find(scope.prefix + node); !output && inside != node_index_.end())
        nodes_with_broken_inputs_.insert(inside->second);
      error(n, fmt::format("'{}' is inside {}: a connection reaches a part only through its ports ({}), as "
                           "'{}.PORT'",
                           node, part->second->describe(), part->second->part.ports(), part->first));
      return {};
    }
  }
  auto it = node_index_.find(scope.prefix + node);
  if (it == node_index_.end() || node.find('/') != std::string::npos) {
    std::vector<std::string> ids;
    for (const auto& [k, _] : node_index_)
      if (k.rfind(scope.prefix, 0) == 0 && k.find('/', scope.prefix.size()) == std::string::npos)
        ids.push_back(k.substr(scope.prefix.size()));
    for (const auto& [k, _] : scope.parts) ids.push_back(k);
    error(n, fmt::format("no node '{}' in the {}{}", node, scope.part_file ? scope.describe() : "graph",
                         did_you_mean(node, ids)));
    return {};
  }
  if (!node_ok_[static_cast<std::size_t>(it->second)]) return {};  // its type is already an error
  const NodeSpec& spec = g_.nodes[static_cast<std::size_t>(it->second)].type->spec;
  const int index = output ? spec.output_index(port) : spec.input_index(port);
  if (index < 0) {
    const auto& ports = output ? spec.outputs() : spec.inputs();
    std::vector<std::string> names;
    for (const auto& p : ports) names.push_back(p.name);
    if (!output) nodes_with_broken_inputs_.insert(it->second);
    std::string hint;
    if ((output ? spec.input_index(port) : spec.output_index(port)) >= 0)
      hint = fmt::format("; '{}' is an {}, and connections go from an output to an input", text,
                         output ? "input" : "output");
    error(n, fmt::format("node '{}' ({}) has no {} '{}'{}{}; its {}s: {}", node, spec.type(), direction, port,
                         did_you_mean(port, names), hint, direction, names.empty() ? "none" : join(names)));
    return {};
  }
  return {Endpoint{it->second, index}};
}

// Each part's declared ports, resolved to its nodes' ports (its own parts' first), with their
// errors in the part's file.
void Builder::resolve_part_ports(Scope& scope) {
  for (auto& [_, inner] : scope.parts) resolve_part_ports(*inner);
  if (!scope.part_file) return;
  const GraphSource::Impl* saved = cur_;
  cur_ = scope.part_file;
  for (const bool output : {false, true})
    for (const PartPort& port : output ? scope.part.outputs : scope.part.inputs) {
      std::vector<Endpoint> resolved;
      for (const PartBinding& b : port.bindings) {
        const auto ends = resolve(scope, b.node, b.name, output, b.yaml);
        for (const Endpoint& e : ends) {
          const NodeSpec& spec = g_.nodes[static_cast<std::size_t>(e.node)].type->spec;
          const std::string type = output ? spec.outputs()[static_cast<std::size_t>(e.port)].type()
                                          : spec.inputs()[static_cast<std::size_t>(e.port)].type();
          if (!port.type.empty() && type != "*" && type != port.type)
            error(b.yaml, fmt::format("the part's {} '{}' is declared {}, but {}.{} is {}", output ? "output" : "input",
                                      port.name, port.type, b.node, b.name, type));
          resolved.push_back(e);
        }
      }
      (output ? scope.outputs : scope.inputs)[port.name] = std::move(resolved);
    }
  cur_ = saved;
}

// Each arg of each part binds a parameter of its own nodes, or an arg of its own parts.
void Builder::check_part_arg_bindings(const Scope& scope) {
  for (const auto& [_, inner] : scope.parts) check_part_arg_bindings(*inner);
  if (!scope.part_file) return;
  const GraphSource::Impl* saved = cur_;
  cur_ = scope.part_file;
  for (const PartArg& arg : scope.part.args)
    for (const PartBinding& b : arg.bindings) {
      if (const auto part = scope.parts.find(b.node); part != scope.parts.end()) {
        if (!part->second->part.arg(b.name))
          error(b.yaml, fmt::format("arg '{}' sets arg '{}' of {}, which has no such arg; its args: {}", arg.name,
                                    b.name, part->second->describe(), join(part->second->part.arg_names())));
        continue;
      }
      if (!node_index_.count(scope.prefix + b.node))
        error(b.yaml, fmt::format("arg '{}' sets '{}.{}', but {} has no node '{}'", arg.name, b.node, b.name,
                                  scope.describe(), b.node));
      // A parameter the node lacks is reported where the arg's value is, as any unknown parameter.
    }
  cur_ = saved;
}

// The values of a part's args (given by its include, or forwarded by the part around it, or their
// defaults) become overrides of the parameters they bind; a value set nearer the top wins.
void Builder::apply_part_args(Scope& scope, const std::map<std::string, Override>& given) {
  std::map<std::string, std::map<std::string, Override>> forwarded;  // inner part -> arg -> value
  if (scope.part_file) {
    for (const auto& [name, value] : given)
      if (!scope.part.arg(name))
        diag_.error(value.where, fmt::format("{} has no arg '{}'{}; its args: {}", scope.describe(), name,
                                             did_you_mean(name, scope.part.arg_names()),
                                             scope.part.args.empty() ? "none" : join(scope.part.arg_names())));
    for (const PartArg& arg : scope.part.args) {
      Override value;
      if (const auto it = given.find(arg.name); it != given.end()) {
        value = it->second;
      } else if (arg.default_value) {
        value = Override{arg.default_value, scope.part_file->at(arg.default_value)};
      } else {
        diag_.error(scope.includer->at(scope.include->entry),
                    fmt::format("{} needs arg '{}'{}", scope.describe(), arg.name,
                                arg.description.empty() ? "" : " (" + arg.description + ")"));
        continue;
      }
      for (const PartBinding& b : arg.bindings) {
        if (scope.parts.count(b.node)) {
          forwarded[b.node].emplace(b.name, value);
        } else {
          overrides_[scope.prefix + b.node].emplace(b.name, value);
          arg_override_nodes_.insert(scope.prefix + b.node);
        }
      }
    }
  }
  for (auto& [as, inner] : scope.parts) {
    std::map<std::string, Override> values = forwarded[as];  // the part around it wins
    const YAML::Node& args = inner->include->args;
    if (args && args.IsMap())
      for (auto it = args.begin(); it != args.end(); ++it)
        values.emplace(it->first.Scalar(), Override{it->second, inner->includer->at(it->first)});
    apply_part_args(*inner, values);
  }
}

void Builder::read_connections() {
  const YAML::Node& root = cur_->root;
  const YAML::Node list = root["connections"];
  if (!list) return;
  if (!list.IsSequence()) {
    error(list, "'connections' must be a list");
    return;
  }
  for (const auto& c : list) {
    if (!check_keys(c, kConnectionKeys, "a connection")) continue;
    const YAML::Node from = c["from"];
    const YAML::Node to = c["to"];
    if (!from || !to) {
      error(c, "a connection needs 'from' (node.output) and 'to' (node.input)");
      continue;
    }
    ConnectionConfig config;
    config.where = at(c);
    config.policy = default_policy_;
    bool ok = true;
    if (const YAML::Node p = c["policy"]) {
      auto text = scalar(p, "policy");
      auto policy = text ? QueuePolicy::parse(*text) : std::nullopt;
      if (!policy) {
        if (text) error(p, fmt::format("bad queue policy '{}': {}", *text, QueuePolicy::kForms));
        ok = false;
      } else {
        config.policy = *policy;
      }
    }
    if (const YAML::Node d = c["delayed"]) {
      if (!d.IsScalar() || !YAML::convert<bool>::decode(d, config.delayed)) {
        error(d, "'delayed' must be true or false");
        ok = false;
      }
    }
    const auto sources = endpoint(from, true);
    const auto targets = endpoint(to, false);
    for (const Endpoint& target : targets) attempted_inputs_.insert({target.node, target.port});
    if (sources.size() != 1 || targets.empty() || !ok) continue;
    const Endpoint& source = sources.front();
    const auto& out_port =
        g_.nodes[static_cast<std::size_t>(source.node)].type->spec.outputs()[static_cast<std::size_t>(source.port)];
    // An input of a part may feed several of its nodes: one connection each.
    for (const Endpoint& target : targets) {
      ConnectionConfig one = config;
      const NodeConfig& to_node = g_.nodes[static_cast<std::size_t>(target.node)];
      const auto& in_port = to_node.type->spec.inputs()[static_cast<std::size_t>(target.port)];
      one.label = fmt::format("{}.{} -> {}.{}", g_.nodes[static_cast<std::size_t>(source.node)].id, out_port.name,
                              to_node.id, in_port.name);
      if (in_port.type() != "*" && in_port.type() != out_port.type()) {
        error(c, fmt::format("port type mismatch: {} is {}, but {} expects {}", from.Scalar(), out_port.type(),
                             targets.size() > 1 ? fmt::format("{} ({})", to.Scalar(), one.label) : to.Scalar(),
                             in_port.type()));
        continue;
      }
      const auto key = std::make_pair(target.node, target.port);
      if (in_port.tap) {
        // A tap takes any number of connections, each output once.
        if (!tapped_.insert({target.node, target.port, source.node, source.port}).second) {
          error(c, fmt::format("{} is already connected to {}", from.Scalar(), to.Scalar()));
          continue;
        }
      } else if (auto prior = input_taken_.find(key); prior != input_taken_.end()) {
        error(to, fmt::format("input {} is already connected ({}); an input takes one connection", to.Scalar(),
                              earlier(prior->second)));
        continue;
      }
      input_taken_[key] = one.where;
      one.from_node = source.node;
      one.from_port = source.port;
      one.to_node = target.node;
      one.to_port = target.port;
      g_.connections.push_back(std::move(one));
    }
  }
}

constexpr std::size_t kTapQueue = 256;  // messages of one output waiting for a tap (realtime)

// Each tap input takes the outputs its topic parameter selects (tap_selection.hpp), in graph
// order, beside those connected to it by hand. An output counts as connected when it feeds an
// input that is not a tap.
void Builder::connect_taps() {
  std::set<std::pair<int, int>> connected;
  for (const auto& c : g_.connections) {
    const auto& in = g_.nodes[static_cast<std::size_t>(c.to_node)].type->spec.inputs();
    if (!in[static_cast<std::size_t>(c.to_port)].tap) connected.insert({c.from_node, c.from_port});
  }
  std::vector<ConnectionConfig> added;
  for (std::size_t t = 0; t < g_.nodes.size(); ++t) {
    if (!node_ok_[t]) continue;
    const NodeConfig& tap_node = g_.nodes[t];
    const auto& inputs = tap_node.type->spec.inputs();
    for (std::size_t p = 0; p < inputs.size(); ++p) {
      if (!inputs[p].tap || !tap_node.params.contains(inputs[p].tap->topics_param)) continue;
      const TopicSelection selection(tap_node.params.get<std::string>(inputs[p].tap->topics_param),
                                     inputs[p].tap->skip_types);
      for (std::size_t n = 0; n < g_.nodes.size(); ++n) {
        if (n == t || !node_ok_[n]) continue;
        const auto& outputs = g_.nodes[n].type->spec.outputs();
        for (std::size_t o = 0; o < outputs.size(); ++o) {
          const int node = static_cast<int>(n), port = static_cast<int>(o);
          if (!selection.selects(output_topic(g_.nodes[n].id, outputs[o].name), outputs[o].type(),
                                 connected.count({node, port}) > 0))
            continue;
          if (!tapped_.insert({static_cast<int>(t), static_cast<int>(p), node, port}).second) continue;
          ConnectionConfig c;
          c.from_node = node;
          c.from_port = port;
          c.to_node = static_cast<int>(t);
          c.to_port = static_cast<int>(p);
          // A tap queues (realtime): `latest` would replace what it has not yet taken, and
          // `block` would make the graph wait for it. A tap that cannot keep up drops and counts.
          c.policy = QueuePolicy{QueuePolicy::Kind::fifo, kTapQueue};
          c.where = tap_node.where;
          c.label = fmt::format("{}.{} -> {}.{} (tap)", g_.nodes[n].id, outputs[o].name, tap_node.id, inputs[p].name);
          added.push_back(std::move(c));
        }
      }
    }
  }
  for (auto& c : added) g_.connections.push_back(std::move(c));
}

void Builder::check_inputs_connected() {
  std::set<std::pair<int, int>> connected;
  for (const auto& c : g_.connections) connected.insert({c.to_node, c.to_port});
  for (std::size_t i = 0; i < g_.nodes.size(); ++i) {
    if (!node_ok_[i] || nodes_with_broken_inputs_.count(static_cast<int>(i))) continue;
    const auto& inputs = g_.nodes[i].type->spec.inputs();
    for (std::size_t p = 0; p < inputs.size(); ++p) {
      const std::pair<int, int> key{static_cast<int>(i), static_cast<int>(p)};
      if (inputs[p].optional || connected.count(key) || attempted_inputs_.count(key)) continue;
      diag_.error(g_.nodes[i].where,
                  fmt::format("input '{}.{}' ({}) is not connected", g_.nodes[i].id, inputs[p].name, inputs[p].type()));
    }
  }
}

// A node that needs the other executor than the one the graph runs under is refused at its type,
// with the reason its spec gives.
void Builder::check_executor_needs(bool executor_from_command_line) {
  const auto name = [](ExecutorKind k) { return k == ExecutorKind::realtime ? "realtime" : "lockstep"; };
  for (std::size_t i = 0; i < g_.nodes.size(); ++i) {
    if (!node_ok_[i]) continue;
    const NodeSpec& spec = g_.nodes[i].type->spec;
    const ExecutorNeed need = spec.executor_need(g_.nodes[i].params);
    if (need == ExecutorNeed::any) continue;
    const ExecutorKind needed = need == ExecutorNeed::realtime ? ExecutorKind::realtime : ExecutorKind::lockstep;
    if (needed == g_.executor) continue;
    diag_.error(
        type_where_[i],
        fmt::format("node '{}' ({}) needs the {} executor{}, but the graph runs {} ({}); set 'executor: "
                    "{}' in the graph or run it with --executor {}",
                    g_.nodes[i].id, spec.type(), name(needed),
                    spec.executor_reason().empty() ? "" : ": " + spec.executor_reason(), name(g_.executor),
                    executor_from_command_line ? "--executor" : "the graph's 'executor'", name(needed), name(needed)));
  }
}

BuildResult Builder::build(const std::vector<std::string>& overrides, const std::vector<const GraphSource*>& fragments,
                           std::optional<ExecutorKind> executor) {
  BuildResult result;
  diag_.append(src_.read_errors);
  for (const GraphSource* fragment : fragments) diag_.append(fragment->impl().read_errors);
  if (diag_.has_errors()) {
    result.diagnostics = diag_;
    return result;
  }
  const YAML::Node& root = src_.root;
  if (!root.IsMap()) {
    diag_.error(at(root), "a graph file must be a YAML map with 'nodes' and 'connections'");
    result.diagnostics = diag_;
    return result;
  }
  g_.file = src_.file;
  check_keys(root, kTopLevelKeys, "the graph");
  read_graph_header(src_.root, yaml_, g_, default_policy_);
  if (executor) {
    g_.executor = *executor;
    g_.clock = *executor == ExecutorKind::realtime ? ClockKind::wall : ClockKind::simulated;
  }
  add_command_line_overrides(overrides, overrides_, diag_);
  add_include_overrides(src_, overrides_, diag_);
  // Included graphs contribute nodes and connections; their header (executor, seed, ...) is the
  // including graph's to choose. Parts take a namespace of their own.
  scopes_.push_back(std::make_unique<Scope>());
  scope_ = scopes_.front().get();
  if (is_part_file(src_))
    diag_.error(at(src_.root),
                "this file is a part, not a runnable graph: a graph includes it with 'part:' and "
                "'as:' (`kestrel inspect` prints its ports and args)");
  collect(src_, *scope_);
  // Fragments from the command line (`kestrel run --record`) add nodes and connections as an
  // included file would.
  for (const GraphSource* fragment : fragments) {
    const GraphSource::Impl& file = fragment->impl();
    cur_ = &file;
    if (!file.root.IsMap())
      diag_.error(at(file.root), "a graph fragment must be a YAML map with 'nodes' and 'connections'");
    else if (check_keys(file.root, {"nodes", "connections"}, "a graph fragment"))
      files_.push_back({&file, scopes_.front().get()});
    cur_ = &src_;
  }
  apply_part_args(*scopes_.front(), {});
  read_fragments();
  check_overrides_name_nodes();
  connect_taps();
  check_inputs_connected();
  check_executor_needs(executor.has_value());
  if (!diag_.has_errors()) order_nodes(g_, diag_);
  diag_.sort();
  result.diagnostics = diag_;
  if (!diag_.has_errors()) result.graph = std::move(g_);
  return result;
}

}  // namespace

BuildResult build_graph(const GraphSource& source, const Registry& registry, const std::vector<std::string>& overrides,
                        const std::vector<const GraphSource*>& fragments, std::optional<ExecutorKind> executor) {
  Builder builder(source.impl(), registry);
  BuildResult result;
  try {
    result = builder.build(overrides, fragments, executor);
  } catch (const YAML::Exception& e) {
    // The checks above guard every access; this is a last line so that a malformed file can never
    // crash the CLI.
    result = BuildResult{};
    result.diagnostics.error(source.impl().at(e.mark), "malformed graph: " + e.msg);
  }
  if (result.graph) result.graph->plugin_paths = source.plugin_paths();
  return result;
}

}  // namespace kestrel
