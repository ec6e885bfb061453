#pragma once
// Private: checks the parameters a graph gives a node (or a component) against its declaration:
// unknown names, types, ranges, allowed values, list lengths, components and their own
// parameters, required parameters, and the rules across parameters. Every problem is reported
// with its file:line:col; nothing is thrown.
#include <map>
#include <optional>
#include <string>

#include "kestrel/registry.hpp"
#include "param_overrides.hpp"
#include "yaml_checks.hpp"

namespace kestrel {

class ParamChecker {
 public:
  ParamChecker(Diagnostics& diag, YamlChecks& yaml, const Registry& registry)
      : diag_(diag), yaml_(yaml), registry_(registry) {}

  /// The validated values of `params` (a YAML map, or absent) with `overrides` applied over them
  /// and defaults filled in; nullopt if anything was wrong. An override named "c.p" sets
  /// parameter p of the component in parameter c (and "c.d.p" one level deeper). `reserved_key`, if set, is a key of
  /// the map that is not a parameter (a component's 'type').
  std::optional<Params> check(const YAML::Node& params, const ParamSet& specs, const std::string& owner,
                              const SourceLocation& owner_where, const std::map<std::string, Override>* overrides,
                              const std::string& reserved_key = {});

 private:
  // A value given for a parameter and where. Values set by --set or an include's `set:` are
  // marked, so that a broken rule points at the setting that overrode the graph.
  struct GivenValue {
    YAML::Node value;
    SourceLocation where;
    bool overridden = false;
  };
  using Given = std::map<std::string, GivenValue>;

  // `nested`: overrides of the parameters of the component this value names, if it is one.
  std::optional<ParamValue> value(const YAML::Node& value, const SourceLocation& where, const ParamSpec& spec,
                                  const std::string& owner, const std::map<std::string, Override>* nested);
  bool in_range(double v, const ParamSpec& spec, const SourceLocation& where, const std::string& owner);
  bool check_rules(const ParamSet& set, const Params& values, const Given& given, const std::string& owner,
                   const SourceLocation& owner_where);

  Diagnostics& diag_;
  YamlChecks& yaml_;
  const Registry& registry_;
};

}  // namespace kestrel
