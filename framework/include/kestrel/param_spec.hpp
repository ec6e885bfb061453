#pragma once
// The declaration of one parameter: name, type, default, unit, range or allowed values, and a
// one-line description. The graph validator, `kestrel inspect` and the docs all read it.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
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

struct ParamSpec {
  std::string name;
  ParamType type = ParamType::number;
  std::optional<ParamValue> default_value;  ///< empty: the graph must set it
  std::string unit;
  std::optional<double> min;  ///< inclusive; numbers, integers and each element of a list
  std::optional<double> max;
  std::vector<std::string> allowed;   ///< for strings: the only accepted values
  std::string component_kind;         ///< for components: e.g. "associator"
  std::optional<std::size_t> length;  ///< for lists: the exact number of elements
  std::string description;

  ParamSpec& with_unit(std::string u) {
    unit = std::move(u);
    return *this;
  }
  ParamSpec& range(double lo, double hi) {
    min = lo;
    max = hi;
    return *this;
  }
  ParamSpec& at_least(double lo) {
    min = lo;
    return *this;
  }
  /// A list of exactly n numbers (e.g. 3 for a position).
  ParamSpec& with_length(std::size_t n) {
    length = n;
    return *this;
  }
  ParamSpec& one_of(std::vector<std::string> values) {
    allowed = std::move(values);
    return *this;
  }
  ParamSpec& describe(std::string text) {
    description = std::move(text);
    return *this;
  }
};

namespace detail {
template <class T>
constexpr ParamType param_type_of() {
  if constexpr (std::is_same_v<T, bool>)
    return ParamType::boolean;
  else if constexpr (std::is_integral_v<T>)
    return ParamType::integer;
  else if constexpr (std::is_floating_point_v<T>)
    return ParamType::number;
  else if constexpr (std::is_convertible_v<T, std::string>)
    return ParamType::string;
  else if constexpr (std::is_same_v<T, std::vector<double>>)
    return ParamType::number_list;
  else
    static_assert(sizeof(T) == 0, "unsupported parameter type");
}

template <class T>
ParamValue to_param_value(T value) {
  if constexpr (std::is_same_v<T, bool>)
    return ParamValue(value);
  else if constexpr (std::is_integral_v<T>)
    return ParamValue(static_cast<std::int64_t>(value));
  else if constexpr (std::is_floating_point_v<T>)
    return ParamValue(static_cast<double>(value));
  else if constexpr (std::is_convertible_v<T, std::string>)
    return ParamValue(std::string(value));
  else
    return ParamValue(std::move(value));
}
}  // namespace detail

/// A parameter of C++ type T (bool, an integer, a floating type, a string or
/// std::vector<double>) with a default value.
template <class T>
ParamSpec param(std::string name, T default_value) {
  ParamSpec spec;
  spec.name = std::move(name);
  spec.type = detail::param_type_of<T>();
  spec.default_value = detail::to_param_value(std::move(default_value));
  return spec;
}

/// A parameter the graph must set.
template <class T>
ParamSpec required_param(std::string name) {
  ParamSpec spec;
  spec.name = std::move(name);
  spec.type = detail::param_type_of<T>();
  return spec;
}

/// A parameter that names a component of `kind` (e.g. "associator"), by default `default_type`.
/// In YAML it is either the component's name or a map {type: NAME, <its params>...}.
ParamSpec component_param(std::string name, std::string kind, std::string default_type);

}  // namespace kestrel
