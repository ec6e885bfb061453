#pragma once
// Problems found while loading plugins or building a graph, each with file:line:col. The builder
// collects every problem before it reports, so a user fixes a graph in one pass.
#include <set>
#include <string>
#include <vector>

#include "kestrel/error.hpp"

namespace kestrel {

struct Diagnostic {
  enum class Severity { error, warning };
  Severity severity = Severity::error;
  SourceLocation where;
  std::string message;

  /// "file:line:col: error: message"
  std::string str() const;
};

class Diagnostics {
 public:
  void error(SourceLocation where, std::string message);
  void warning(SourceLocation where, std::string message);
  void append(const Diagnostics& other);

  bool has_errors() const;
  std::size_t error_count() const;
  const std::vector<Diagnostic>& items() const { return items_; }
  /// Orders by file, then line, then column; stable for equal positions.
  void sort();
  /// Every diagnostic, one per line.
  std::string str() const;

 private:
  void add(Diagnostic::Severity severity, SourceLocation where, std::string message);
  std::vector<Diagnostic> items_;
  std::set<std::string> said_;  // each item's str(): a diagnostic is said once
};

/// The closest candidate to `word` by edit distance, or "" if none is close enough to be a
/// plausible typo.
std::string nearest_name(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace kestrel
