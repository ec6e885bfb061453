#include "kestrel/error.hpp"

#include <fmt/format.h>

namespace kestrel {

std::string SourceLocation::str() const {
  if (line <= 0) return file;
  if (column <= 0) return fmt::format("{}:{}", file, line);
  return fmt::format("{}:{}:{}", file, line, column);
}

}  // namespace kestrel
