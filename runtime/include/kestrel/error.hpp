#pragma once
// Errors that kestrel reports to users: a message and, where known, where it came from.
#include <stdexcept>
#include <string>

namespace kestrel {

/// A place in a source file, 1-based. line == 0 means "no position known".
struct SourceLocation {
  std::string file;
  int line = 0;
  int column = 0;

  /// "file:line:col", "file" or "" depending on what is known.
  std::string str() const;
};

/// Every error kestrel throws to a user is (or derives from) this type.
class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
  Error(SourceLocation where, const std::string& message)
      : std::runtime_error(where.line > 0 || !where.file.empty() ? where.str() + ": " + message : message),
        where_(std::move(where)) {}

  const SourceLocation& where() const { return where_; }

 private:
  SourceLocation where_;
};

}  // namespace kestrel
