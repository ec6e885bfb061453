#pragma once
// Private: the parsed YAML behind a GraphSource, and how YAML positions become locations.
#include <yaml-cpp/yaml.h>

#include "kestrel/runtime/graph.hpp"

namespace kestrel {

struct GraphSource::Impl {
  std::string label;            // what error messages call the file
  std::filesystem::path file;   // empty for a string source
  YAML::Node root;
  Diagnostics read_errors;

  SourceLocation at(const YAML::Mark& mark) const {
    if (mark.line < 0) return SourceLocation{label, 0, 0};
    return SourceLocation{label, mark.line + 1, mark.column + 1};
  }
  SourceLocation at(const YAML::Node& node) const { return at(node.Mark()); }
};

}  // namespace kestrel
