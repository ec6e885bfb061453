#pragma once
// Private: the small checks every part of graph reading makes on YAML nodes, reporting into
// Diagnostics with the node's file:line:col.
#include <yaml-cpp/yaml.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "kestrel/runtime/diagnostics.hpp"

namespace kestrel {

/// Where a YAML node is, in the file being read.
using Locate = std::function<SourceLocation(const YAML::Node&)>;

/// A node id or a part's namespace: a letter or '_', then letters, digits, '_' and '-'.
bool valid_node_id(const std::string& id);

/// "a, b, c".
std::string join(const std::vector<std::string>& items);
/// " (did you mean 'x'?)" for the nearest candidate, or "" if none is near.
std::string did_you_mean(const std::string& word, const std::vector<std::string>& candidates);

class YamlChecks {
 public:
  YamlChecks(Diagnostics& diag, Locate locate) : diag_(diag), locate_(std::move(locate)) {}

  void error(const YAML::Node& n, std::string message) { diag_.error(locate_(n), std::move(message)); }
  SourceLocation at(const YAML::Node& n) const { return locate_(n); }

  /// Checks that `map` is a map whose keys are all in `allowed` (and not repeated).
  bool keys(const YAML::Node& map, const std::vector<std::string>& allowed, const std::string& what);
  std::optional<std::string> scalar(const YAML::Node& n, const std::string& what);
  /// A finite number.
  std::optional<double> number(const YAML::Node& n, const std::string& what);

 private:
  Diagnostics& diag_;
  Locate locate_;
};

}  // namespace kestrel
