#include "yaml_checks.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>

namespace kestrel {

bool valid_node_id(const std::string& id) {
  if (id.empty() || !(std::isalpha(static_cast<unsigned char>(id[0])) || id[0] == '_')) return false;
  for (unsigned char c : id)
    if (!(std::isalnum(c) || c == '_' || c == '-')) return false;
  return true;
}

std::string join(const std::vector<std::string>& items) { return fmt::format("{}", fmt::join(items, ", ")); }

std::string did_you_mean(const std::string& word, const std::vector<std::string>& candidates) {
  const std::string near = nearest_name(word, candidates);
  return near.empty() ? std::string() : " (did you mean '" + near + "'?)";
}

bool YamlChecks::keys(const YAML::Node& map, const std::vector<std::string>& allowed, const std::string& what) {
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

std::optional<std::string> YamlChecks::scalar(const YAML::Node& n, const std::string& what) {
  if (!n.IsScalar()) {
    error(n, what + " must be a single value");
    return std::nullopt;
  }
  return n.Scalar();
}

std::optional<double> YamlChecks::number(const YAML::Node& n, const std::string& what) {
  double v = 0;
  if (!n.IsScalar() || !YAML::convert<double>::decode(n, v) || !std::isfinite(v)) {
    error(n, fmt::format("{} must be a number, not '{}'", what, n.IsScalar() ? n.Scalar() : "a structure"));
    return std::nullopt;
  }
  return v;
}

}  // namespace kestrel
