// The queue policies of realtime connections: how they are written in YAML and shown.
#include <fmt/format.h>

#include <sstream>

#include "kestrel/runtime/graph.hpp"

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

}  // namespace kestrel
