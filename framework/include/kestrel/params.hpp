#pragma once
// The validated parameter values a node or component is built with.
#include <Eigen/Core>
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "kestrel/error.hpp"
#include "kestrel/param_spec.hpp"

namespace kestrel {

/// Every declared parameter, with the graph's value or the declared default. Values have been
/// checked against their declaration before a node sees them.
class Params {
 public:
  Params() = default;

  void set(const std::string& name, ParamValue value) { values_[name] = std::move(value); }
  bool contains(const std::string& name) const { return values_.count(name) != 0; }
  const std::map<std::string, ParamValue>& values() const { return values_; }

  /// The value of `name` as T. Throws kestrel::Error if the parameter was not declared or has
  /// another type; integers widen to floating point on request.
  template <class T>
  T get(const std::string& name) const;

 private:
  const ParamValue& at(const std::string& name) const;
  std::map<std::string, ParamValue> values_;
};

template <class T>
T Params::get(const std::string& name) const {
  const ParamValue& v = at(name);
  if constexpr (std::is_same_v<T, bool>) {
    if (auto* b = std::get_if<bool>(&v)) return *b;
  } else if constexpr (std::is_integral_v<T>) {
    if (auto* i = std::get_if<std::int64_t>(&v)) {
      if (*i < static_cast<std::int64_t>(std::numeric_limits<T>::min()) ||
          static_cast<std::uint64_t>(*i) > static_cast<std::uint64_t>(std::numeric_limits<T>::max()))
        throw Error("parameter '" + name + "' = " + std::to_string(*i) + " does not fit the node's integer type");
      return static_cast<T>(*i);
    }
  } else if constexpr (std::is_floating_point_v<T>) {
    if (auto* d = std::get_if<double>(&v)) return static_cast<T>(*d);
    if (auto* i = std::get_if<std::int64_t>(&v)) return static_cast<T>(*i);
  } else if constexpr (std::is_same_v<T, std::string>) {
    if (auto* s = std::get_if<std::string>(&v)) return *s;
  } else if constexpr (std::is_same_v<T, std::vector<double>>) {
    if (auto* l = std::get_if<std::vector<double>>(&v)) return *l;
  } else if constexpr (std::is_same_v<T, Eigen::Vector3d>) {
    // A position or offset: a list of three numbers (declare it with .with_length(3)).
    if (auto* l = std::get_if<std::vector<double>>(&v); l && l->size() == 3) return {(*l)[0], (*l)[1], (*l)[2]};
  } else if constexpr (std::is_same_v<T, ComponentConfig>) {
    if (auto* c = std::get_if<ComponentConfig>(&v)) return *c;
  } else {
    static_assert(sizeof(T) == 0, "unsupported parameter type");
  }
  throw Error("parameter '" + name + "' holds " + to_string(v) + ", which is not of the type the node asked for");
}

}  // namespace kestrel
