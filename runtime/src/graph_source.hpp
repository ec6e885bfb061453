#pragma once
// Private: the parsed YAML behind a GraphSource, the graphs it includes, and how YAML positions
// become locations.
#include <yaml-cpp/yaml.h>

#include <memory>
#include <vector>

#include "kestrel/runtime/graph.hpp"

namespace kestrel {

struct GraphSource::Impl {
  std::string label;           // what error messages call the file
  std::filesystem::path file;  // empty for a string source
  YAML::Node root;
  Diagnostics read_errors;  // reading, YAML syntax and include entries, of this file and those it includes

  /// One entry of this file's `include:` list, already read (recursively): a file whose nodes
  /// join the includer's (`file:`, with `set:`), or a part under a namespace of its own (`part:`,
  /// `as:`, `args:`; graph_part.hpp).
  struct Include {
    std::unique_ptr<Impl> source;
    YAML::Node set;    // the entry's `set:` map of node.param: value, or an invalid node
    YAML::Node entry;  // the entry itself, where errors about it point
    std::string as;    // a part's namespace; empty for a file
    YAML::Node args;   // a part's `args:` map, or an invalid node
    bool part() const { return !as.empty(); }
  };
  std::vector<Include> includes;

  SourceLocation at(const YAML::Mark& mark) const {
    if (mark.line < 0) return SourceLocation{label, 0, 0};
    return SourceLocation{label, mark.line + 1, mark.column + 1};
  }
  SourceLocation at(const YAML::Node& node) const { return at(node.Mark()); }

  /// The folder relative paths in this file are resolved against.
  std::filesystem::path folder() const;
};

}  // namespace kestrel
