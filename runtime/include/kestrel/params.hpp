#pragma once
// The validated parameter values a node or component is built with.
#include <map>
#include <string>

#include "kestrel/error.hpp"
#include "kestrel/param_codec.hpp"
#include "kestrel/param_value.hpp"

namespace kestrel {

/// Every declared parameter, with the graph's value or the declared default. Values have been
/// checked against their declaration before a node sees them.
class Params {
 public:
  Params() = default;

  void set(const std::string& name, ParamValue value) { values_[name] = std::move(value); }
  bool contains(const std::string& name) const { return values_.count(name) != 0; }
  const std::map<std::string, ParamValue>& values() const { return values_; }
  /// The stored value; throws kestrel::Error if the parameter was not declared.
  const ParamValue& at(const std::string& name) const;

  /// The value of `name` as T (any type ParamCodec knows). Throws kestrel::Error if the parameter
  /// was not declared or has another type; integers widen to floating point on request.
  template <class T>
  T get(const std::string& name) const {
    return ParamCodec<T>::decode(at(name), name);
  }

 private:
  std::map<std::string, ParamValue> values_;
};

}  // namespace kestrel
