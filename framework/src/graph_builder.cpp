// Validates a graph's YAML against the registry and builds a GraphConfig. Every check lives
// here, and every problem is collected (not thrown) with its file:line:col, so that
// `kestrel validate` reports them all in one pass.
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <sstream>

#include "graph_source.hpp"

namespace kestrel {

std::string QueuePolicy::str() const {
  switch (kind) {
    case Kind::latest:
      return "latest";
    case Kind::fifo:
      return fmt::format("fifo {}", capacity);
    case Kind::block:
      return fmt::format("block {}", capacity);
  }
  return "?";
}

std::optional<QueuePolicy> QueuePolicy::parse(const std::string& text) {
  std::istringstream in(text);
  std::string word;
  in >> word;
  QueuePolicy policy;
  if (word == "latest") {
    policy.kind = Kind::latest;
    policy.capacity = 1;
  } else if (word == "fifo" || word == "block") {
    policy.kind = word == "fifo" ? Kind::fifo : Kind::block;
    long long n = word == "fifo" ? 16 : 1;
    if (!(in >> std::ws).eof() && !(in >> n)) return std::nullopt;
    if (n < 1) return std::nullopt;
    policy.capacity = static_cast<std::size_t>(n);
  } else {
    return std::nullopt;
  }
  std::string rest;
  if (in >> rest) return std::nullopt;
  return policy;
}

namespace {

const std::vector<std::string> kTopLevelKeys = {"kestrel",  "name",     "description", "plugin_paths",
                                                "include",  "executor", "clock",       "seed",
                                                "duration", "on_error", "nodes",       "connections"};
const std::vector<std::string> kNodeKeys = {"id", "type", "params", "description"};
const std::vector<std::string> kConnectionKeys = {"from", "to", "policy", "delayed"};
const char* kPolicyForms = "expected 'latest', 'fifo N' or 'block N'";

std::string join(const std::vector<std::string>& items) { return fmt::format("{}", fmt::join(items, ", ")); }

std::string did_you_mean(const std::string& word, const std::vector<std::string>& candidates) {
  const std::string near = nearest_name(word, candidates);
  return near.empty() ? std::string() : " (did you mean '" + near + "'?)";
}

bool valid_id(const std::string& id) {
  if (id.empty() || !(std::isalpha(static_cast<unsigned char>(id[0])) || id[0] == '_')) return false;
  for (unsigned char c : id)
    if (!(std::isalnum(c) || c == '_' || c == '-')) return false;
  return true;
}

struct Override {
  YAML::Node value;
  SourceLocation where;
};

class Builder {
 public:
  Builder(const GraphSource::Impl& src, const Registry& registry) : src_(src), cur_(&src), registry_(registry) {}

  BuildResult build(const std::vector<std::string>& overrides);

 private:
  SourceLocation at(const YAML::Node& n) const { return cur_->at(n); }
  // Where an earlier definition is, as seen from the file being read: "line N" in the same file.
  std::string earlier(const SourceLocation& where) const {
    return where.file == cur_->label ? fmt::format("line {}", where.line) : where.str();
  }
  void error(const YAML::Node& n, std::string message) { diag_.error(at(n), std::move(message)); }

  // Checks that `map` is a map whose keys are all in `allowed` (and not repeated).
  bool check_keys(const YAML::Node& map, const std::vector<std::string>& allowed, const std::string& what);
  std::optional<std::string> scalar(const YAML::Node& n, const std::string& what);
  std::optional<double> number(const YAML::Node& n, const std::string& what);

  void read_header();
  void read_executor(const YAML::Node& n);
  void read_clock(const YAML::Node& n, bool& clock_given);
  void read_fragments();
  void check_overrides_name_nodes();
  void add_include_sets(const GraphSource::Impl& file);
  void read_nodes();
  void read_connections();
  void check_inputs_connected();
  void order_nodes();
  void parse_overrides(const std::vector<std::string>& overrides);

  // `reserved_key`, if set, is a key of the map that is not a parameter (a component's 'type').
  std::optional<Params> check_params(const YAML::Node& params, const std::vector<ParamSpec>& specs,
                                     const std::string& owner, const SourceLocation& owner_where,
                                     const std::map<std::string, Override>* overrides,
                                     const std::string& reserved_key = {});
  std::optional<ParamValue> check_value(const YAML::Node& value, const SourceLocation& where, const ParamSpec& spec,
                                        const std::string& owner);
  bool in_range(double v, const ParamSpec& spec, const SourceLocation& where, const std::string& owner);

  struct Endpoint {
    int node = -1;
    int port = -1;
  };
  std::optional<Endpoint> endpoint(const YAML::Node& n, bool output);

  const GraphSource::Impl& src_;
  const GraphSource::Impl* cur_;                 // the file being read: the graph or one it includes
  std::vector<const GraphSource::Impl*> files_;  // included files depth-first, then the graph itself
  const Registry& registry_;
  Diagnostics diag_;
  GraphConfig g_;
  QueuePolicy default_policy_;
  std::map<std::string, int> node_index_;
  std::map<std::string, std::map<std::string, Override>> overrides_;  // node id -> param -> value
  std::vector<bool> node_ok_;                                         // type known (ports can be checked)
  // Inputs named by a connection that failed for another reason: not also "not connected".
  std::set<std::pair<int, int>> attempted_inputs_;
  std::set<int> nodes_with_broken_inputs_;
  std::map<std::pair<int, int>, SourceLocation> input_taken_;  // (node, input) -> its connection
};

bool Builder::check_keys(const YAML::Node& map, const std::vector<std::string>& allowed, const std::string& what) {
  if (!map.IsMap()) {
    error(map, what + " must be a map");
    return false;
  }
  std::set<std::string> seen;
  for (auto it = map.begin(); it != map.end(); ++it) {
    const std::string key = it->first.Scalar();
    if (!seen.insert(key).second) error(it->first, fmt::format("duplicate key '{}' in {}", key, what));
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end())
      error(it->first, fmt::format("unknown key '{}' in {}{}; allowed keys: {}", key, what, did_you_mean(key, allowed),
                                   join(allowed)));
  }
  return true;
}

std::optional<std::string> Builder::scalar(const YAML::Node& n, const std::string& what) {
  if (!n.IsScalar()) {
    error(n, what + " must be a single value");
    return std::nullopt;
  }
  return n.Scalar();
}

std::optional<double> Builder::number(const YAML::Node& n, const std::string& what) {
  double v = 0;
  if (!n.IsScalar() || !YAML::convert<double>::decode(n, v) || !std::isfinite(v)) {
    error(n, fmt::format("{} must be a number, not '{}'", what, n.IsScalar() ? n.Scalar() : "a structure"));
    return std::nullopt;
  }
  return v;
}

void Builder::read_executor(const YAML::Node& n) {
  // yaml-cpp: assigning to a Node writes through to the tree, so pick the node at construction.
  const YAML::Node type = n.IsMap() ? n["type"] : n;
  if (n.IsMap()) {
    check_keys(n, {"type", "default_policy"}, "executor");
    if (!type) {
      error(n, "executor needs a 'type' (lockstep or realtime)");
      return;
    }
    if (const YAML::Node p = n["default_policy"]) {
      if (auto text = scalar(p, "default_policy")) {
        if (auto policy = QueuePolicy::parse(*text))
          default_policy_ = *policy;
        else
          error(p, fmt::format("bad queue policy '{}': {}", *text, kPolicyForms));
      }
    }
  }
  if (auto name = scalar(type, "executor")) {
    if (*name == "lockstep")
      g_.executor = ExecutorKind::lockstep;
    else if (*name == "realtime")
      g_.executor = ExecutorKind::realtime;
    else
      error(type, fmt::format("unknown executor '{}'{}; executors: lockstep, realtime", *name,
                              did_you_mean(*name, {"lockstep", "realtime"})));
  }
}

void Builder::read_clock(const YAML::Node& n, bool& clock_given) {
  const YAML::Node type = n.IsMap() ? n["type"] : n;
  if (n.IsMap()) {
    check_keys(n, {"type", "real_time_factor"}, "clock");
    if (!type) {
      error(n, "clock needs a 'type' (simulated or wall)");
      return;
    }
    if (const YAML::Node f = n["real_time_factor"]) {
      if (auto v = number(f, "real_time_factor")) {
        if (*v <= 0)
          error(f, "real_time_factor must be positive");
        else
          g_.real_time_factor = *v;
      }
    }
  }
  if (auto name = scalar(type, "clock")) {
    clock_given = true;
    if (*name == "simulated")
      g_.clock = ClockKind::simulated;
    else if (*name == "wall")
      g_.clock = ClockKind::wall;
    else
      error(type, fmt::format("unknown clock '{}'{}; clocks: simulated, wall", *name,
                              did_you_mean(*name, {"simulated", "wall"})));
  }
}

void Builder::read_header() {
  const YAML::Node& root = src_.root;
  if (const YAML::Node v = root["kestrel"]) {
    long version = 0;
    if (!v.IsScalar() || !YAML::convert<long>::decode(v, version) || version != 1)
      error(v, "unsupported graph format version '" + (v.IsScalar() ? v.Scalar() : std::string("?")) +
                   "'; this kestrel reads version 1");
  }
  if (const YAML::Node v = root["name"])
    if (auto s = scalar(v, "name")) g_.name = *s;
  if (const YAML::Node v = root["description"])
    if (auto s = scalar(v, "description")) g_.description = *s;
  if (const YAML::Node v = root["plugin_paths"]) {
    if (!v.IsSequence()) error(v, "plugin_paths must be a list of folders");
    for (const auto& p : v)
      if (!p.IsScalar()) error(p, "each plugin path must be a folder name");
  }
  if (const YAML::Node v = root["executor"]) read_executor(v);
  bool clock_given = false;
  if (const YAML::Node v = root["clock"]) read_clock(v, clock_given);
  if (!clock_given) g_.clock = g_.executor == ExecutorKind::realtime ? ClockKind::wall : ClockKind::simulated;
  if (g_.executor == ExecutorKind::realtime && g_.clock == ClockKind::simulated)
    error(root["clock"], "the realtime executor runs on the wall clock; use 'clock: wall' or the lockstep executor");
  if (const YAML::Node v = root["seed"]) {
    std::uint64_t seed = 0;
    if (!v.IsScalar() || !YAML::convert<std::uint64_t>::decode(v, seed) ||
        (!v.Scalar().empty() && v.Scalar()[0] == '-'))
      error(v, "seed must be a non-negative integer");
    else
      g_.seed = seed;
  }
  if (const YAML::Node v = root["duration"]) {
    if (auto d = number(v, "duration")) {
      if (*d <= 0)
        error(v, "duration must be positive (seconds)");
      else
        g_.duration_s = *d;
    }
  }
  if (const YAML::Node v = root["on_error"]) {
    if (auto s = scalar(v, "on_error")) {
      if (*s == "stop")
        g_.on_error = ErrorPolicy::stop;
      else if (*s == "skip")
        g_.on_error = ErrorPolicy::skip;
      else
        error(v, fmt::format("unknown on_error policy '{}'{}; policies: stop, skip", *s,
                             did_you_mean(*s, {"stop", "skip"})));
    }
  }
}

void Builder::parse_overrides(const std::vector<std::string>& overrides) {
  for (const auto& text : overrides) {
    const SourceLocation where{"--set " + text, 0, 0};
    const auto eq = text.find('=');
    const auto dot = text.find('.');
    if (eq == std::string::npos || dot == std::string::npos || dot > eq || dot == 0 || dot + 1 == eq) {
      diag_.error(where, "expected --set node.param=value");
      continue;
    }
    const std::string node = text.substr(0, dot);
    const std::string param = text.substr(dot + 1, eq - dot - 1);
    YAML::Node value;
    try {
      value = YAML::Load(text.substr(eq + 1));
    } catch (const YAML::Exception& e) {
      diag_.error(where, "the value is not valid YAML: " + e.msg);
      continue;
    }
    if (value.IsNull() && text.substr(eq + 1).empty()) {
      diag_.error(where, "no value after '='");
      continue;
    }
    overrides_[node][param] = Override{value, where};
  }
}

bool Builder::in_range(double v, const ParamSpec& spec, const SourceLocation& where, const std::string& owner) {
  if ((spec.min && v < *spec.min) || (spec.max && v > *spec.max)) {
    std::string range = fmt::format("[{}, {}]", spec.min ? fmt::format("{}", *spec.min) : "-inf",
                                    spec.max ? fmt::format("{}", *spec.max) : "inf");
    diag_.error(where, fmt::format("{}: parameter '{}' = {} is out of range {}{}", owner, spec.name, v, range,
                                   spec.unit.empty() ? "" : " " + spec.unit));
    return false;
  }
  return true;
}

std::optional<ParamValue> Builder::check_value(const YAML::Node& value, const SourceLocation& where,
                                               const ParamSpec& spec, const std::string& owner) {
  auto wrong_type = [&](const std::string& expected) {
    diag_.error(where, fmt::format("{}: parameter '{}' must be {}, not '{}'", owner, spec.name, expected,
                                   value.IsScalar() ? value.Scalar() : (value.IsSequence() ? "a list" : "a map")));
    return std::nullopt;
  };
  switch (spec.type) {
    case ParamType::boolean: {
      bool b = false;
      if (!value.IsScalar() || !YAML::convert<bool>::decode(value, b)) return wrong_type("true or false");
      return ParamValue(b);
    }
    case ParamType::integer: {
      long long i = 0;
      if (!value.IsScalar() || !YAML::convert<long long>::decode(value, i)) return wrong_type("an integer");
      if (!in_range(static_cast<double>(i), spec, where, owner)) return std::nullopt;
      return ParamValue(static_cast<std::int64_t>(i));
    }
    case ParamType::number: {
      double d = 0;
      bool is_bool = false;
      if (!value.IsScalar() || YAML::convert<bool>::decode(value, is_bool) ||
          !YAML::convert<double>::decode(value, d) || !std::isfinite(d))
        return wrong_type("a number");
      if (!in_range(d, spec, where, owner)) return std::nullopt;
      return ParamValue(d);
    }
    case ParamType::string: {
      if (!value.IsScalar()) return wrong_type("a string");
      const std::string s = value.Scalar();
      if (!spec.allowed.empty() && std::find(spec.allowed.begin(), spec.allowed.end(), s) == spec.allowed.end()) {
        diag_.error(where, fmt::format("{}: parameter '{}' = '{}' is not one of {}{}", owner, spec.name, s,
                                       join(spec.allowed), did_you_mean(s, spec.allowed)));
        return std::nullopt;
      }
      return ParamValue(s);
    }
    case ParamType::number_list: {
      if (!value.IsSequence()) return wrong_type("a list of numbers");
      std::vector<double> list;
      bool ok = true;
      for (const auto& item : value) {
        double d = 0;
        if (!item.IsScalar() || !YAML::convert<double>::decode(item, d) || !std::isfinite(d)) {
          diag_.error(at(item), fmt::format("{}: parameter '{}' must hold numbers only", owner, spec.name));
          ok = false;
        } else if (!in_range(d, spec, at(item), owner)) {
          ok = false;
        }
        list.push_back(d);
      }
      if (ok && spec.length && list.size() != *spec.length) {
        diag_.error(where, fmt::format("{}: parameter '{}' must hold exactly {} numbers, not {}", owner, spec.name,
                                       *spec.length, list.size()));
        ok = false;
      }
      if (!ok) return std::nullopt;
      return ParamValue(std::move(list));
    }
    case ParamType::component: {
      // Either a name, or a map with 'type' and the component's own parameters (read in place,
      // so that their positions survive).
      const YAML::Node type_node = value.IsMap() ? value["type"] : value;
      const YAML::Node component_params = value.IsMap() ? value : YAML::Node();
      if (value.IsMap() && !type_node) {
        diag_.error(where, fmt::format("{}: parameter '{}' needs a 'type' naming the {}", owner, spec.name,
                                       spec.component_kind));
        return std::nullopt;
      }
      if (!type_node.IsScalar()) return wrong_type("a " + spec.component_kind + " name or a map with 'type'");
      const std::string name = type_node.Scalar();
      const ComponentType* component = registry_.find_component(spec.component_kind, name);
      const SourceLocation type_where = value.IsMap() ? at(type_node) : where;
      if (!component) {
        const auto known = registry_.component_names(spec.component_kind);
        diag_.error(type_where, fmt::format("{}: unknown {} '{}'{}; known: {}", owner, spec.component_kind, name,
                                            did_you_mean(name, known), known.empty() ? "none" : join(known)));
        return std::nullopt;
      }
      auto params = check_params(component_params, component->spec.params(),
                                 fmt::format("{} {} '{}'", owner, spec.component_kind, name), where, nullptr, "type");
      if (!params) return std::nullopt;
      return ParamValue(ComponentConfig{name, std::make_shared<const Params>(std::move(*params))});
    }
  }
  return std::nullopt;
}

std::optional<Params> Builder::check_params(const YAML::Node& params, const std::vector<ParamSpec>& specs,
                                            const std::string& owner, const SourceLocation& owner_where,
                                            const std::map<std::string, Override>* overrides,
                                            const std::string& reserved_key) {
  std::vector<std::string> names;
  for (const auto& s : specs) names.push_back(s.name);
  auto find_spec = [&](const std::string& name) -> const ParamSpec* {
    for (const auto& s : specs)
      if (s.name == name) return &s;
    return nullptr;
  };
  auto unknown = [&](const SourceLocation& where, const std::string& name) {
    diag_.error(where, fmt::format("{}: unknown parameter '{}'{}; parameters: {}", owner, name,
                                   did_you_mean(name, names), names.empty() ? "none" : join(names)));
  };

  bool ok = true;
  std::map<std::string, std::pair<YAML::Node, SourceLocation>> given;
  if (params && !params.IsNull()) {
    if (!params.IsMap()) {
      diag_.error(at(params), owner + ": params must be a map of name: value");
      return std::nullopt;
    }
    for (auto it = params.begin(); it != params.end(); ++it) {
      const std::string name = it->first.Scalar();
      if (!reserved_key.empty() && name == reserved_key) continue;
      if (given.count(name)) {
        error(it->first, fmt::format("{}: parameter '{}' is given twice", owner, name));
        ok = false;
      }
      if (!find_spec(name)) {
        unknown(at(it->first), name);
        ok = false;
        continue;
      }
      given[name] = {it->second, at(it->second)};
    }
  }
  if (overrides) {
    for (const auto& [name, o] : *overrides) {
      if (!find_spec(name)) {
        unknown(o.where, name);
        ok = false;
        continue;
      }
      given[name] = {o.value, o.where};
    }
  }

  Params result;
  for (const auto& spec : specs) {
    auto it = given.find(spec.name);
    if (it == given.end()) {
      if (spec.default_value)
        result.set(spec.name, *spec.default_value);
      else {
        diag_.error(owner_where,
                    fmt::format("{}: required parameter '{}' ({}) is not set", owner, spec.name, to_string(spec.type)));
        ok = false;
      }
      continue;
    }
    if (auto value = check_value(it->second.first, it->second.second, spec, owner))
      result.set(spec.name, std::move(*value));
    else
      ok = false;
  }
  if (!ok) return std::nullopt;
  return result;
}

// Every file's nodes, then every file's connections, so that a graph can connect to the nodes of
// the graphs it includes.
void Builder::read_fragments() {
  bool any_nodes = false;
  for (const auto* file : files_) {
    cur_ = file;
    const YAML::Node& root = file->root;
    if (root["nodes"]) any_nodes = true;
    read_nodes();
  }
  cur_ = &src_;
  if (!any_nodes) diag_.error(at(src_.root), "the graph has no 'nodes' list");
  for (const auto* file : files_) {
    cur_ = file;
    read_connections();
  }
  cur_ = &src_;
}

// An include's `set:` entries, outer files first: a value set nearer the top wins (and --set
// over all of them, as it was parsed before).
void Builder::add_include_sets(const GraphSource::Impl& file) {
  for (const auto& include : file.includes) {
    if (!include.set) continue;
    for (auto it = include.set.begin(); it != include.set.end(); ++it) {
      const std::string key = it->first.Scalar();
      const auto dot = key.find('.');
      if (dot == std::string::npos || dot == 0 || dot + 1 == key.size()) {
        diag_.error(file.at(it->first), "an include's 'set' key is node.param, not '" + key + "'");
        continue;
      }
      overrides_[key.substr(0, dot)].emplace(key.substr(dot + 1), Override{it->second, file.at(it->first)});
    }
  }
  for (const auto& include : file.includes) add_include_sets(*include.source);
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
    config.id = *id_text;
    if (!valid_id(config.id)) {
      error(id, fmt::format("node id '{}' must start with a letter or '_' and hold only letters, digits, '_' and '-'",
                            config.id));
      continue;
    }
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
      auto params = check_params(n["params"], config.type->spec.params(), owner, config.where,
                                 ov == overrides_.end() ? nullptr : &ov->second);
      if (params) config.params = std::move(*params);
    }
    node_index_[config.id] = static_cast<int>(g_.nodes.size());
    node_ok_.push_back(config.type != nullptr);
    g_.nodes.push_back(std::move(config));
  }
}

void Builder::check_overrides_name_nodes() {
  for (const auto& [node, params] : overrides_) {
    if (node_index_.count(node)) continue;
    for (const auto& [_, o] : params)
      diag_.error(o.where, fmt::format("no node '{}' in the graph{}", node, did_you_mean(node, [&] {
                                         std::vector<std::string> ids;
                                         for (const auto& [k, _] : node_index_) ids.push_back(k);
                                         return ids;
                                       }())));
  }
}

std::optional<Builder::Endpoint> Builder::endpoint(const YAML::Node& n, bool output) {
  const char* direction = output ? "output" : "input";
  auto text = scalar(n, output ? "'from'" : "'to'");
  if (!text) return std::nullopt;
  const auto dot = text->find('.');
  if (dot == std::string::npos || dot == 0 || dot + 1 == text->size()) {
    error(n, fmt::format("'{}' must be node.port", *text));
    return std::nullopt;
  }
  const std::string node = text->substr(0, dot);
  const std::string port = text->substr(dot + 1);
  auto it = node_index_.find(node);
  if (it == node_index_.end()) {
    std::vector<std::string> ids;
    for (const auto& [k, _] : node_index_) ids.push_back(k);
    error(n, fmt::format("no node '{}' in the graph{}", node, did_you_mean(node, ids)));
    return std::nullopt;
  }
  if (!node_ok_[static_cast<std::size_t>(it->second)]) return std::nullopt;  // its type is already an error
  const NodeSpec& spec = g_.nodes[static_cast<std::size_t>(it->second)].type->spec;
  const int index = output ? spec.output_index(port) : spec.input_index(port);
  if (index < 0) {
    const auto& ports = output ? spec.outputs() : spec.inputs();
    std::vector<std::string> names;
    for (const auto& p : ports) names.push_back(p.name);
    if (!output) nodes_with_broken_inputs_.insert(it->second);
    std::string hint;
    if ((output ? spec.input_index(port) : spec.output_index(port)) >= 0)
      hint = fmt::format("; '{}' is an {}, and connections go from an output to an input", *text,
                         output ? "input" : "output");
    error(n, fmt::format("node '{}' ({}) has no {} '{}'{}{}; its {}s: {}", node, spec.type(), direction, port,
                         did_you_mean(port, names), hint, direction, names.empty() ? "none" : join(names)));
    return std::nullopt;
  }
  return Endpoint{it->second, index};
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
        if (text) error(p, fmt::format("bad queue policy '{}': {}", *text, kPolicyForms));
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
    auto source = endpoint(from, true);
    auto target = endpoint(to, false);
    if (target) attempted_inputs_.insert({target->node, target->port});
    if (!source || !target || !ok) continue;
    const auto& out_port =
        g_.nodes[static_cast<std::size_t>(source->node)].type->spec.outputs()[static_cast<std::size_t>(source->port)];
    const auto& in_port =
        g_.nodes[static_cast<std::size_t>(target->node)].type->spec.inputs()[static_cast<std::size_t>(target->port)];
    config.label = from.Scalar() + " -> " + to.Scalar();
    if (in_port.type != "*" && in_port.type != out_port.type) {
      error(c, fmt::format("port type mismatch: {} is {}, but {} expects {}", from.Scalar(), out_port.type, to.Scalar(),
                           in_port.type));
      continue;
    }
    const auto key = std::make_pair(target->node, target->port);
    if (auto prior = input_taken_.find(key); prior != input_taken_.end()) {
      error(to, fmt::format("input {} is already connected ({}); an input takes one connection", to.Scalar(),
                            earlier(prior->second)));
      continue;
    }
    input_taken_[key] = config.where;
    config.from_node = source->node;
    config.from_port = source->port;
    config.to_node = target->node;
    config.to_port = target->port;
    g_.connections.push_back(std::move(config));
  }
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
                  fmt::format("input '{}.{}' ({}) is not connected", g_.nodes[i].id, inputs[p].name, inputs[p].type));
    }
  }
}

void Builder::order_nodes() {
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

BuildResult Builder::build(const std::vector<std::string>& overrides) {
  BuildResult result;
  diag_.append(src_.read_errors);
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
  read_header();
  parse_overrides(overrides);
  add_include_sets(src_);
  // Included graphs contribute nodes and connections; their header (executor, seed, ...) is the
  // including graph's to choose.
  std::function<void(const GraphSource::Impl&)> collect = [&](const GraphSource::Impl& file) {
    for (const auto& include : file.includes) collect(*include.source);
    if (&file != &src_) {
      cur_ = &file;
      if (!file.root.IsMap())
        diag_.error(at(file.root), "an included graph file must be a YAML map with 'nodes' and 'connections'");
      else if (check_keys(file.root, kTopLevelKeys, "the included graph"))
        files_.push_back(&file);
      cur_ = &src_;
      return;
    }
    files_.push_back(&file);
  };
  collect(src_);
  read_fragments();
  check_overrides_name_nodes();
  check_inputs_connected();
  if (!diag_.has_errors()) order_nodes();
  diag_.sort();
  result.diagnostics = diag_;
  if (!diag_.has_errors()) result.graph = std::move(g_);
  return result;
}

}  // namespace

BuildResult build_graph(const GraphSource& source, const Registry& registry,
                        const std::vector<std::string>& overrides) {
  Builder builder(source.impl(), registry);
  BuildResult result;
  try {
    result = builder.build(overrides);
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
