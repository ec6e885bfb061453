// The graph file's header: format version, name, executor, clock, seed, duration and error
// policy.
#include "graph_header.hpp"

#include <fmt/format.h>

namespace kestrel {

namespace {

void read_executor(const YAML::Node& n, YamlChecks& yaml, GraphConfig& g_, QueuePolicy& default_policy_) {
  // yaml-cpp: assigning to a Node writes through to the tree, so pick the node at construction.
  const YAML::Node type = n.IsMap() ? n["type"] : n;
  if (n.IsMap()) {
    yaml.keys(n, {"type", "default_policy"}, "executor");
    if (!type) {
      yaml.error(n, "executor needs a 'type' (lockstep or realtime)");
      return;
    }
    if (const YAML::Node p = n["default_policy"]) {
      if (auto text = yaml.scalar(p, "default_policy")) {
        if (auto policy = QueuePolicy::parse(*text))
          default_policy_ = *policy;
        else
          yaml.error(p, fmt::format("bad queue policy '{}': {}", *text, QueuePolicy::kForms));
      }
    }
  }
  if (auto name = yaml.scalar(type, "executor")) {
    if (*name == "lockstep")
      g_.executor = ExecutorKind::lockstep;
    else if (*name == "realtime")
      g_.executor = ExecutorKind::realtime;
    else
      yaml.error(type, fmt::format("unknown executor '{}'{}; executors: lockstep, realtime", *name,
                                   did_you_mean(*name, {"lockstep", "realtime"})));
  }
}

void read_clock(const YAML::Node& n, bool& clock_given, YamlChecks& yaml, GraphConfig& g_) {
  const YAML::Node type = n.IsMap() ? n["type"] : n;
  if (n.IsMap()) {
    yaml.keys(n, {"type", "real_time_factor"}, "clock");
    if (!type) {
      yaml.error(n, "clock needs a 'type' (simulated or wall)");
      return;
    }
    if (const YAML::Node f = n["real_time_factor"]) {
      if (auto v = yaml.number(f, "real_time_factor")) {
        if (*v <= 0)
          yaml.error(f, "real_time_factor must be positive");
        else
          g_.real_time_factor = *v;
      }
    }
  }
  if (auto name = yaml.scalar(type, "clock")) {
    clock_given = true;
    if (*name == "simulated")
      g_.clock = ClockKind::simulated;
    else if (*name == "wall")
      g_.clock = ClockKind::wall;
    else
      yaml.error(type, fmt::format("unknown clock '{}'{}; clocks: simulated, wall", *name,
                                   did_you_mean(*name, {"simulated", "wall"})));
  }
}

}  // namespace

void read_graph_header(const YAML::Node& root, YamlChecks& yaml, GraphConfig& g_, QueuePolicy& default_policy_) {
  if (const YAML::Node v = root["kestrel"]) {
    long version = 0;
    if (!v.IsScalar() || !YAML::convert<long>::decode(v, version) || version != 1)
      yaml.error(v, "unsupported graph format version '" + (v.IsScalar() ? v.Scalar() : std::string("?")) +
                        "'; this kestrel reads version 1");
  }
  if (const YAML::Node v = root["name"])
    if (auto s = yaml.scalar(v, "name")) g_.name = *s;
  if (const YAML::Node v = root["description"])
    if (auto s = yaml.scalar(v, "description")) g_.description = *s;
  if (const YAML::Node v = root["plugin_paths"]) {
    if (!v.IsSequence()) yaml.error(v, "plugin_paths must be a list of folders");
    for (const auto& p : v)
      if (!p.IsScalar()) yaml.error(p, "each plugin path must be a folder name");
  }
  if (const YAML::Node v = root["executor"]) read_executor(v, yaml, g_, default_policy_);
  bool clock_given = false;
  if (const YAML::Node v = root["clock"]) read_clock(v, clock_given, yaml, g_);
  if (!clock_given) g_.clock = g_.executor == ExecutorKind::realtime ? ClockKind::wall : ClockKind::simulated;
  if (g_.executor == ExecutorKind::realtime && g_.clock == ClockKind::simulated)
    yaml.error(root["clock"],
               "the realtime executor runs on the wall clock; use 'clock: wall' or the lockstep executor");
  if (const YAML::Node v = root["seed"]) {
    std::uint64_t seed = 0;
    if (!v.IsScalar() || !YAML::convert<std::uint64_t>::decode(v, seed) ||
        (!v.Scalar().empty() && v.Scalar()[0] == '-'))
      yaml.error(v, "seed must be a non-negative integer");
    else
      g_.seed = seed;
  }
  if (const YAML::Node v = root["duration"]) {
    if (auto d = yaml.number(v, "duration")) {
      if (*d <= 0)
        yaml.error(v, "duration must be positive (seconds)");
      else
        g_.duration_s = *d;
    }
  }
  if (const YAML::Node v = root["on_error"]) {
    if (auto s = yaml.scalar(v, "on_error")) {
      if (*s == "stop")
        g_.on_error = ErrorPolicy::stop;
      else if (*s == "skip")
        g_.on_error = ErrorPolicy::skip;
      else
        yaml.error(v, fmt::format("unknown on_error policy '{}'{}; policies: stop, skip", *s,
                                  did_you_mean(*s, {"stop", "skip"})));
    }
  }
}

}  // namespace kestrel
