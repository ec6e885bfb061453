#pragma once
// The declaration of one parameter: name, type, default, unit, range or allowed values, and a
// one-line description; and of the rules that tie parameters together. The graph validator,
// `kestrel inspect` and the docs all read it. Nodes normally declare parameters through a
// ConfigSpec (kestrel/config_spec.hpp), which binds each one to a field of a config struct.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <typeinfo>
#include <vector>

#include "kestrel/param_codec.hpp"
#include "kestrel/param_value.hpp"

namespace kestrel {

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
  /// Writes a validated value into the field of a config struct it is bound to (empty if the
  /// parameter is not bound).
  std::function<void(void* config, const ParamValue&)> bind;

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
  ParamSpec& at_most(double hi) {
    max = hi;
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

/// A condition over several parameters (for example min_points <= max_points). The validator
/// reports a violation with the file:line:col of a parameter it names.
struct ParamRule {
  std::string text;                 ///< the condition as a user reads it: "min_points <= max_points"
  std::vector<std::string> params;  ///< the parameters it reads
  std::function<bool(const void* config)> holds;
  bool defaults_may_break = false;  ///< a choice the graph must make (ConfigSpec::requirement)
};

/// Every parameter of a node or component, the rules between them, and how to build the config
/// struct they are bound to.
struct ParamSet {
  std::vector<ParamSpec> params;
  std::vector<ParamRule> rules;
  /// A default-constructed config struct (null when nothing is bound).
  std::function<std::shared_ptr<void>()> make_config;
  const std::type_info* config_type = nullptr;

  const ParamSpec* find(std::string_view name) const;
  /// The config struct with every bound parameter set from `values`.
  std::shared_ptr<void> build_config(const Params& values) const;
  /// The rules that `values` break (empty if all hold or nothing is bound).
  std::vector<const ParamRule*> broken_rules(const Params& values) const;
};

/// A parameter of C++ type T with a default value, read with Params::get<T>.
template <class T>
ParamSpec param(std::string name, T default_value) {
  using Codec =
      ParamCodec<std::conditional_t<std::is_convertible_v<T, std::string> && !std::is_same_v<T, bool>, std::string, T>>;
  ParamSpec spec;
  spec.name = std::move(name);
  spec.type = Codec::type;
  if constexpr (std::is_convertible_v<T, std::string> && !std::is_same_v<T, bool>)
    spec.default_value = Codec::encode(std::string(default_value));
  else
    spec.default_value = Codec::encode(default_value);
  if (Codec::length > 0) spec.length = Codec::length;
  return spec;
}

/// A parameter the graph must set.
template <class T>
ParamSpec required_param(std::string name) {
  ParamSpec spec;
  spec.name = std::move(name);
  spec.type = ParamCodec<T>::type;
  if (ParamCodec<T>::length > 0) spec.length = ParamCodec<T>::length;
  return spec;
}

/// A parameter that names a component of `kind` (e.g. "associator"), by default `default_type`.
/// In YAML it is either the component's name or a map {type: NAME, <its params>...}.
ParamSpec component_param(std::string name, std::string kind, std::string default_type);

/// The problems of a declaration, checked when a plugin registers it: duplicate or empty names,
/// empty descriptions, defaults outside their range or allowed values, lists of the wrong length,
/// rules that name unknown parameters or that the defaults break. Empty if it is sound.
std::vector<std::string> check_param_set(const ParamSet& set);

}  // namespace kestrel
