#pragma once
// Private: parameter values set from outside a node's own `params:` map: `--set node.param=value`
// on the command line and an include's `set:` map. Both win over the graph's values.
#include <yaml-cpp/yaml.h>

#include <map>
#include <string>
#include <vector>

#include "graph_source.hpp"
#include "kestrel/runtime/diagnostics.hpp"

namespace kestrel {

struct Override {
  YAML::Node value;
  SourceLocation where;
};

/// node id -> parameter -> value.
using Overrides = std::map<std::string, std::map<std::string, Override>>;

/// Parses `--set node.param=value` texts; each bad one is an error located at "--set TEXT".
void add_command_line_overrides(const std::vector<std::string>& texts, Overrides& out, Diagnostics& diag);

/// Adds the `set:` maps of the includes of `file` and of the files they include, outer files
/// first, without replacing a value already set: a value set nearer the top wins (and --set, if
/// added before, over all of them).
void add_include_overrides(const GraphSource::Impl& file, Overrides& out, Diagnostics& diag);

}  // namespace kestrel
