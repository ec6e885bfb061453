// A declaration's parameters as a whole: building the bound config struct, evaluating the rules,
// and the soundness checks a plugin's declaration must pass when it registers.
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <set>

#include "kestrel/param_spec.hpp"
#include "kestrel/params.hpp"

namespace kestrel {

const ParamSpec* ParamSet::find(std::string_view name) const {
  for (const auto& p : params)
    if (p.name == name) return &p;
  return nullptr;
}

std::shared_ptr<void> ParamSet::build_config(const Params& values) const {
  if (!make_config) return nullptr;
  std::shared_ptr<void> config = make_config();
  for (const auto& spec : params)
    if (spec.bind && values.contains(spec.name)) spec.bind(config.get(), values.at(spec.name));
  return config;
}

std::vector<const ParamRule*> ParamSet::broken_rules(const Params& values) const {
  std::vector<const ParamRule*> broken;
  if (rules.empty() || !make_config) return broken;
  const std::shared_ptr<void> config = build_config(values);
  for (const auto& rule : rules)
    if (!rule.holds(config.get())) broken.push_back(&rule);
  return broken;
}

namespace {

bool valid_name(const std::string& name) {
  if (name.empty() || !(std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_')) return false;
  return std::all_of(name.begin(), name.end(), [](unsigned char c) { return std::isalnum(c) || c == '_'; });
}

// The problems of one default value against its own declaration.
void check_default(const ParamSpec& p, std::vector<std::string>& problems) {
  if (!p.default_value) return;
  const ParamValue& v = *p.default_value;
  const bool type_matches = (p.type == ParamType::boolean && std::holds_alternative<bool>(v)) ||
                            (p.type == ParamType::integer && std::holds_alternative<std::int64_t>(v)) ||
                            (p.type == ParamType::number && std::holds_alternative<double>(v)) ||
                            (p.type == ParamType::string && std::holds_alternative<std::string>(v)) ||
                            (p.type == ParamType::number_list && std::holds_alternative<std::vector<double>>(v)) ||
                            (p.type == ParamType::component && std::holds_alternative<ComponentConfig>(v));
  if (!type_matches) {
    problems.push_back(
        fmt::format("parameter '{}': the default {} is not a {}", p.name, to_string(v), to_string(p.type)));
    return;
  }
  auto out_of_range = [&](double x) { return (p.min && x < *p.min) || (p.max && x > *p.max); };
  auto range_text = [&] {
    return fmt::format("[{}, {}]", p.min ? fmt::format("{}", *p.min) : "-inf",
                       p.max ? fmt::format("{}", *p.max) : "inf");
  };
  if (auto* i = std::get_if<std::int64_t>(&v); i && out_of_range(static_cast<double>(*i)))
    problems.push_back(fmt::format("parameter '{}': the default {} is outside its range {}", p.name, *i, range_text()));
  if (auto* d = std::get_if<double>(&v); d && out_of_range(*d))
    problems.push_back(fmt::format("parameter '{}': the default {} is outside its range {}", p.name, *d, range_text()));
  if (auto* l = std::get_if<std::vector<double>>(&v)) {
    if (p.length && l->size() != *p.length)
      problems.push_back(fmt::format("parameter '{}': the default has {} numbers, but the parameter takes {}", p.name,
                                     l->size(), *p.length));
    if (std::any_of(l->begin(), l->end(), out_of_range))
      problems.push_back(fmt::format("parameter '{}': the default {} has an element outside the range {}", p.name,
                                     to_string(v), range_text()));
  }
  if (auto* s = std::get_if<std::string>(&v);
      s && !p.allowed.empty() && std::find(p.allowed.begin(), p.allowed.end(), *s) == p.allowed.end())
    problems.push_back(fmt::format("parameter '{}': the default '{}' is not one of its allowed values", p.name, *s));
  if (auto* c = std::get_if<ComponentConfig>(&v); c && c->type.empty())
    problems.push_back(fmt::format("parameter '{}': a component parameter needs a default component", p.name));
}

}  // namespace

std::vector<std::string> check_param_set(const ParamSet& set) {
  std::vector<std::string> problems;
  std::set<std::string> names;
  bool all_defaults = true;
  for (const auto& p : set.params) {
    if (!valid_name(p.name))
      problems.push_back(
          fmt::format("parameter name '{}' must start with a letter or '_' and hold only letters, "
                      "digits and '_'",
                      p.name));
    if (!names.insert(p.name).second) problems.push_back(fmt::format("parameter '{}' is declared twice", p.name));
    if (p.description.empty()) problems.push_back(fmt::format("parameter '{}' has no description", p.name));
    if (p.min && p.max && *p.min > *p.max)
      problems.push_back(fmt::format("parameter '{}': its range [{}, {}] is empty", p.name, *p.min, *p.max));
    if (p.type == ParamType::component && p.component_kind.empty())
      problems.push_back(fmt::format("parameter '{}': a component parameter needs a kind", p.name));
    check_default(p, problems);
    if (!p.default_value) all_defaults = false;
  }
  for (const auto& rule : set.rules) {
    if (rule.text.empty()) problems.push_back("a rule has no text to show when it is broken");
    if (rule.params.empty()) problems.push_back(fmt::format("rule '{}' names no parameter", rule.text));
    for (const auto& name : rule.params)
      if (!names.count(name))
        problems.push_back(fmt::format("rule '{}' names an undeclared parameter '{}'", rule.text, name));
  }
  // The defaults themselves must satisfy the rules; otherwise every graph that leaves them alone
  // would be invalid. A requirement is the exception: the graph must choose.
  if (problems.empty() && all_defaults && set.make_config) {
    Params defaults;
    for (const auto& p : set.params) defaults.set(p.name, *p.default_value);
    for (const ParamRule* rule : set.broken_rules(defaults))
      if (!rule->defaults_may_break) problems.push_back(fmt::format("the defaults break the rule '{}'", rule->text));
  }
  return problems;
}

}  // namespace kestrel
