#pragma once
// The value a parameter holds once a graph has been validated: one of six types.
#include <cstdint>
#include <memory>
#include <string>
#include <variant>
#include <vector>

namespace kestrel {

class Params;

enum class ParamType { boolean, integer, number, string, number_list, component };

/// "bool", "int", "float", "string", "float list" or "component".
const char* to_string(ParamType type);

/// The value of a component parameter: which registered component to build, with its own
/// parameters (already validated against that component's declaration).
struct ComponentConfig {
  std::string type;
  std::shared_ptr<const Params> params;
};

using ParamValue = std::variant<bool, std::int64_t, double, std::string, std::vector<double>, ComponentConfig>;

/// Human-readable rendering of a value, as YAML would write it.
std::string to_string(const ParamValue& value);

}  // namespace kestrel
