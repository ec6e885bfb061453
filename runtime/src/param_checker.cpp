#include "param_checker.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>

namespace kestrel {

bool ParamChecker::in_range(double v, const ParamSpec& spec, const SourceLocation& where, const std::string& owner) {
  if ((spec.min && v < *spec.min) || (spec.max && v > *spec.max)) {
    std::string range = fmt::format("[{}, {}]", spec.min ? fmt::format("{}", *spec.min) : "-inf",
                                    spec.max ? fmt::format("{}", *spec.max) : "inf");
    diag_.error(where, fmt::format("{}: parameter '{}' = {} is out of range {}{}", owner, spec.name, v, range,
                                   spec.unit.empty() ? "" : " " + spec.unit));
    return false;
  }
  return true;
}

std::optional<ParamValue> ParamChecker::value(const YAML::Node& value, const SourceLocation& where,
                                              const ParamSpec& spec, const std::string& owner,
                                              const std::map<std::string, Override>* nested) {
  auto wrong_type = [&](const std::string& expected) {
    diag_.error(where, fmt::format("{}: parameter '{}' must be {}, not '{}'", owner, spec.name, expected,
                                   value.IsScalar() ? value.Scalar() : (value.IsSequence() ? "a list" : "a map")));
    return std::nullopt;
  };
  switch (spec.type) {
    case ParamType::boolean: {
      bool b = false;
      if (!value.IsScalar() || !YAML::convert<bool>::decode(value, b)) return wrong_type("true or false");
      return ParamValue(b);
    }
    case ParamType::integer: {
      long long i = 0;
      if (!value.IsScalar() || !YAML::convert<long long>::decode(value, i)) return wrong_type("an integer");
      if (!in_range(static_cast<double>(i), spec, where, owner)) return std::nullopt;
      return ParamValue(static_cast<std::int64_t>(i));
    }
    case ParamType::number: {
      double d = 0;
      bool is_bool = false;
      if (!value.IsScalar() || YAML::convert<bool>::decode(value, is_bool) ||
          !YAML::convert<double>::decode(value, d) || !std::isfinite(d))
        return wrong_type("a number");
      if (!in_range(d, spec, where, owner)) return std::nullopt;
      return ParamValue(d);
    }
    case ParamType::string: {
      if (!value.IsScalar()) return wrong_type("a string");
      const std::string s = value.Scalar();
      if (!spec.allowed.empty() && std::find(spec.allowed.begin(), spec.allowed.end(), s) == spec.allowed.end()) {
        diag_.error(where, fmt::format("{}: parameter '{}' = '{}' is not one of {}{}", owner, spec.name, s,
                                       join(spec.allowed), did_you_mean(s, spec.allowed)));
        return std::nullopt;
      }
      return ParamValue(s);
    }
    case ParamType::number_list: {
      if (!value.IsSequence()) return wrong_type("a list of numbers");
      std::vector<double> list;
      bool ok = true;
      for (const auto& item : value) {
        double d = 0;
        if (!item.IsScalar() || !YAML::convert<double>::decode(item, d) || !std::isfinite(d)) {
          diag_.error(yaml_.at(item), fmt::format("{}: parameter '{}' must hold numbers only", owner, spec.name));
          ok = false;
        } else if (!in_range(d, spec, yaml_.at(item), owner)) {
          ok = false;
        }
        list.push_back(d);
      }
      if (ok && spec.length && list.size() != *spec.length) {
        diag_.error(where, fmt::format("{}: parameter '{}' must hold exactly {} numbers, not {}", owner, spec.name,
                                       *spec.length, list.size()));
        ok = false;
      }
      if (!ok) return std::nullopt;
      return ParamValue(std::move(list));
    }
    case ParamType::component: {
      // Either a name, or a map with 'type' and the component's own parameters (read in place,
      // so that their positions survive).
      const YAML::Node type_node = value.IsMap() ? value["type"] : value;
      const YAML::Node component_params = value.IsMap() ? value : YAML::Node();
      if (value.IsMap() && !type_node) {
        diag_.error(where, fmt::format("{}: parameter '{}' needs a 'type' naming the {}", owner, spec.name,
                                       spec.component_kind));
        return std::nullopt;
      }
      if (!type_node.IsScalar()) return wrong_type("a " + spec.component_kind + " name or a map with 'type'");
      const std::string name = type_node.Scalar();
      const ComponentType* component = registry_.find_component(spec.component_kind, name);
      const SourceLocation type_where = value.IsMap() ? yaml_.at(type_node) : where;
      if (!component) {
        const auto known = registry_.component_names(spec.component_kind);
        diag_.error(type_where, fmt::format("{}: unknown {} '{}'{}; known: {}", owner, spec.component_kind, name,
                                            did_you_mean(name, known), known.empty() ? "none" : join(known)));
        return std::nullopt;
      }
      auto params = check(component_params, component->spec.param_set(),
                          fmt::format("{} {} '{}'", owner, spec.component_kind, name), where, nested, "type");
      if (!params) return std::nullopt;
      return ParamValue(ComponentConfig{name, std::make_shared<const Params>(std::move(*params))});
    }
  }
  return std::nullopt;
}

std::optional<Params> ParamChecker::check(const YAML::Node& params, const ParamSet& set, const std::string& owner,
                                          const SourceLocation& owner_where,
                                          const std::map<std::string, Override>* overrides,
                                          const std::string& reserved_key) {
  const auto& specs = set.params;
  std::vector<std::string> names;
  for (const auto& s : specs) names.push_back(s.name);
  auto find_spec = [&](const std::string& name) { return set.find(name); };
  auto unknown = [&](const SourceLocation& where, const std::string& name) {
    diag_.error(where, fmt::format("{}: unknown parameter '{}'{}; parameters: {}", owner, name,
                                   did_you_mean(name, names), names.empty() ? "none" : join(names)));
  };

  bool ok = true;
  Given given;
  if (params && !params.IsNull()) {
    if (!params.IsMap()) {
      diag_.error(yaml_.at(params), owner + ": params must be a map of name: value");
      return std::nullopt;
    }
    for (auto it = params.begin(); it != params.end(); ++it) {
      const std::string name = it->first.Scalar();
      if (!reserved_key.empty() && name == reserved_key) continue;
      if (given.count(name)) {
        yaml_.error(it->first, fmt::format("{}: parameter '{}' is given twice", owner, name));
        ok = false;
      }
      if (!find_spec(name)) {
        unknown(yaml_.at(it->first), name);
        ok = false;
        continue;
      }
      given[name] = {it->second, yaml_.at(it->second), false};
    }
  }
  // An override of "filter.r" sets parameter r of the component in parameter filter.
  std::map<std::string, std::map<std::string, Override>> nested;
  if (overrides) {
    for (const auto& [name, o] : *overrides) {
      const auto dot = name.find('.');
      const std::string head = name.substr(0, dot);
      const ParamSpec* spec = find_spec(head);
      if (!spec) {
        unknown(o.where, head);
        ok = false;
      } else if (dot != std::string::npos && spec->type != ParamType::component) {
        diag_.error(o.where,
                    fmt::format("{}: parameter '{}' is not a component, so '{}' names nothing", owner, head, name));
        ok = false;
      } else if (dot != std::string::npos) {
        nested[head][name.substr(dot + 1)] = o;
      } else {
        given[name] = {o.value, o.where, true};
      }
    }
  }
  // A component left at its default is read as if its name had been given, so that its own
  // parameters get their defaults (and any overrides) and are checked.
  for (const auto& spec : specs) {
    if (spec.type != ParamType::component || given.count(spec.name) || !spec.default_value) continue;
    const auto sub = nested.find(spec.name);
    given[spec.name] = {YAML::Node(std::get<ComponentConfig>(*spec.default_value).type),
                        sub == nested.end() ? owner_where : sub->second.begin()->second.where, sub != nested.end()};
  }

  Params result;
  for (const auto& spec : specs) {
    auto it = given.find(spec.name);
    if (it == given.end()) {
      if (spec.default_value)
        result.set(spec.name, *spec.default_value);
      else {
        diag_.error(owner_where,
                    fmt::format("{}: required parameter '{}' ({}) is not set", owner, spec.name, to_string(spec.type)));
        ok = false;
      }
      continue;
    }
    const auto sub = nested.find(spec.name);
    if (auto value =
            this->value(it->second.value, it->second.where, spec, owner, sub == nested.end() ? nullptr : &sub->second))
      result.set(spec.name, std::move(*value));
    else
      ok = false;
  }
  if (!ok) return std::nullopt;
  if (!check_rules(set, result, given, owner, owner_where)) return std::nullopt;
  return result;
}

// Rules are checked once every value is valid on its own. A broken rule is reported where one of
// the parameters it names was set (the graph's own value, an include's or --set).
bool ParamChecker::check_rules(const ParamSet& set, const Params& values, const Given& given, const std::string& owner,
                               const SourceLocation& owner_where) {
  const auto broken = set.broken_rules(values);
  for (const ParamRule* rule : broken) {
    const GivenValue* at = nullptr;
    std::vector<std::string> shown;
    for (const auto& name : rule->params) {
      if (auto it = given.find(name); it != given.end() && (!at || (it->second.overridden && !at->overridden)))
        at = &it->second;
      if (values.contains(name)) shown.push_back(fmt::format("{} = {}", name, to_string(values.at(name))));
    }
    const SourceLocation where = at ? at->where : owner_where;
    diag_.error(where, fmt::format("{}: {} break the rule '{}'", owner, fmt::join(shown, ", "), rule->text));
  }
  return broken.empty();
}

}  // namespace kestrel
