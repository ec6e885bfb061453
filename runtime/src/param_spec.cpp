#include "kestrel/param_spec.hpp"

#include <fmt/format.h>

#include "kestrel/param_spec.hpp"
#include "kestrel/params.hpp"

namespace kestrel {

const char* to_string(ParamType type) {
  switch (type) {
    case ParamType::boolean:
      return "bool";
    case ParamType::integer:
      return "int";
    case ParamType::number:
      return "float";
    case ParamType::string:
      return "string";
    case ParamType::number_list:
      return "float list";
    case ParamType::component:
      return "component";
  }
  return "?";
}

std::string to_string(const ParamValue& value) {
  struct Visitor {
    std::string operator()(bool b) const { return b ? "true" : "false"; }
    std::string operator()(std::int64_t i) const { return std::to_string(i); }
    std::string operator()(double d) const { return fmt::format("{}", d); }
    std::string operator()(const std::string& s) const { return s; }
    std::string operator()(const std::vector<double>& l) const { return fmt::format("[{}]", fmt::join(l, ", ")); }
    std::string operator()(const ComponentConfig& c) const {
      if (!c.params || c.params->values().empty()) return c.type;
      std::vector<std::string> parts{"type: " + c.type};
      for (const auto& [k, v] : c.params->values()) parts.push_back(k + ": " + to_string(v));
      return fmt::format("{{{}}}", fmt::join(parts, ", "));
    }
  };
  return std::visit(Visitor{}, value);
}

namespace detail {
void throw_wrong_type(const std::string& name, const ParamValue& value, const char* wanted) {
  throw Error("parameter '" + name + "' holds " + to_string(value) + ", which is not a " + wanted +
              " as the node asked for");
}
}  // namespace detail

ParamSpec component_param(std::string name, std::string kind, std::string default_type) {
  ParamSpec spec;
  spec.name = std::move(name);
  spec.type = ParamType::component;
  spec.component_kind = std::move(kind);
  spec.default_value = ComponentConfig{std::move(default_type), nullptr};
  return spec;
}

const ParamValue& Params::at(const std::string& name) const {
  auto it = values_.find(name);
  if (it == values_.end()) throw Error("parameter '" + name + "' is not declared in the node's spec()");
  return it->second;
}

}  // namespace kestrel
