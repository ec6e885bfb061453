#pragma once
// Parameters declared once, bound to the fields of a config struct. The field's type gives the
// parameter's type and its initial value in Config{} gives the default, so a node states each
// parameter in one place:
//
//   struct ClusterConfig {
//     double tolerance_m = 0.5;
//     int min_points = 20;
//     int max_points = 200;
//   };
//   kestrel::ConfigSpec<ClusterConfig> c;
//   c.param("tolerance_m", &ClusterConfig::tolerance_m).with_unit("m").at_least(0.0).describe("...");
//   c.param("min_points", &ClusterConfig::min_points).at_least(1).describe("...");
//   c.param("max_points", &ClusterConfig::max_points).at_least(1).describe("...");
//   c.rule("min_points <= max_points", {"min_points", "max_points"},
//          [](const ClusterConfig& k) { return k.min_points <= k.max_points; });
//   ... NodeSpec(...).config(std::move(c));              // in spec()
//   ... cfg_(init.config<ClusterConfig>())               // in the constructor
#include <deque>
#include <functional>
#include <memory>
#include <string>
#include <type_traits>
#include <typeinfo>
#include <utility>
#include <vector>

#include "kestrel/param_spec.hpp"
#include "kestrel/params.hpp"

namespace kestrel {

template <class Config>
class ConfigSpec {
  static_assert(std::is_default_constructible_v<Config> && std::is_copy_constructible_v<Config>,
                "a config struct must be default-constructible (its defaults are the parameters' defaults) and "
                "copyable");

 public:
  /// A parameter bound to `field`; its default is the field's value in Config{}.
  template <class T>
  ParamSpec& param(std::string name, T Config::*field) {
    return bind<T>(
        std::move(name), [field](Config& c) -> T& { return c.*field; }, true);
  }

  /// A parameter bound to a field of a nested struct (shared groups such as scoring settings).
  template <class Group, class T>
  ParamSpec& param(std::string name, Group Config::*group, T Group::*field) {
    return bind<T>(
        std::move(name), [group, field](Config& c) -> T& { return (c.*group).*field; }, true);
  }

  /// A parameter the graph must set, bound to `field`.
  template <class T>
  ParamSpec& required(std::string name, T Config::*field) {
    return bind<T>(
        std::move(name), [field](Config& c) -> T& { return c.*field; }, false);
  }

  /// A string parameter with fixed choices, each mapped to a value of the enum field.
  template <class E>
  ParamSpec& choice(std::string name, E Config::*field, std::vector<std::pair<std::string, E>> options) {
    return bind_choice<E>(
        std::move(name), [field](Config& c) -> E& { return c.*field; }, std::move(options));
  }

  /// The same, bound to an enum field of a nested struct.
  template <class Group, class E>
  ParamSpec& choice(std::string name, Group Config::*group, E Group::*field,
                    std::vector<std::pair<std::string, E>> options) {
    return bind_choice<E>(
        std::move(name), [group, field](Config& c) -> E& { return (c.*group).*field; }, std::move(options));
  }

  /// A component parameter (e.g. the associator of a tracker), bound to a ComponentConfig field
  /// that NodeInit::make_component or ComponentInit::make_component builds from.
  ParamSpec& component(std::string name, ComponentConfig Config::*field, std::string kind, std::string default_type) {
    ParamSpec& spec = push_spec(component_param(std::move(name), std::move(kind), std::move(default_type)));
    spec.bind = [field, n = spec.name](void* config, const ParamValue& v) {
      static_cast<Config*>(config)->*field = ParamCodec<ComponentConfig>::decode(v, n);
    };
    return spec;
  }

  /// A condition over parameters, checked by the validator with the position of the parameters
  /// it names. `text` says the condition as a user would write it.
  ConfigSpec& rule(std::string text, std::vector<std::string> params, std::function<bool(const Config&)> holds) {
    rules_.push_back(ParamRule{std::move(text), std::move(params), [holds = std::move(holds)](const void* config) {
                                 return holds(*static_cast<const Config*>(config));
                               }});
    return *this;
  }

  /// A rule that asks the graph to choose, as a required parameter does, among several: "left and
  /// right, or video". The defaults may break it (they choose nothing); a graph may not.
  ConfigSpec& requirement(std::string text, std::vector<std::string> params, std::function<bool(const Config&)> holds) {
    rule(std::move(text), std::move(params), std::move(holds));
    rules_.back().defaults_may_break = true;
    return *this;
  }

  /// Hands the declaration over to a NodeSpec or ComponentSpec.
  ParamSet release() && {
    ParamSet set;
    set.params.assign(std::make_move_iterator(params_.begin()), std::make_move_iterator(params_.end()));
    set.rules = std::move(rules_);
    set.make_config = [] { return std::static_pointer_cast<void>(std::make_shared<Config>()); };
    set.config_type = &typeid(Config);
    return set;
  }

 private:
  template <class E, class Access>
  ParamSpec& bind_choice(std::string name, Access access, std::vector<std::pair<std::string, E>> options) {
    static_assert(std::is_enum_v<E>, "choice() binds an enum field");
    ParamSpec& spec = push(std::move(name), ParamType::string);
    Config defaults{};
    const E initial = access(defaults);
    for (const auto& [text, value] : options) {
      spec.allowed.push_back(text);
      if (value == initial) spec.default_value = ParamValue(text);
    }
    spec.bind = [access, options](void* config, const ParamValue& v) {
      const auto& text = std::get<std::string>(v);
      for (const auto& [t, value] : options)
        if (t == text) access(*static_cast<Config*>(config)) = value;
    };
    return spec;
  }

  template <class T, class Access>
  ParamSpec& bind(std::string name, Access access, bool with_default) {
    using Codec = ParamCodec<T>;
    ParamSpec& spec = push(std::move(name), Codec::type);
    if (with_default) {
      Config initial{};
      spec.default_value = Codec::encode(access(initial));
    }
    if (Codec::length > 0) spec.length = Codec::length;
    spec.bind = [access, n = spec.name](void* config, const ParamValue& v) {
      access(*static_cast<Config*>(config)) = Codec::decode(v, n);
    };
    return spec;
  }

  ParamSpec& push(std::string name, ParamType type) {
    ParamSpec spec;
    spec.name = std::move(name);
    spec.type = type;
    return push_spec(std::move(spec));
  }
  // A deque keeps the references handed out for chaining valid while more are added.
  ParamSpec& push_spec(ParamSpec spec) { return params_.emplace_back(std::move(spec)); }

  std::deque<ParamSpec> params_;
  std::vector<ParamRule> rules_;
};

namespace detail {
/// The config struct `set` binds, built from `values`; throws if the struct is not `Config`.
template <class Config>
Config config_from(const ParamSet& set, const Params& values, const std::string& owner) {
  if (!set.config_type || *set.config_type != typeid(Config))
    throw Error(owner + ": spec() binds no parameters to the config struct asked for (use ConfigSpec<" +
                typeid(Config).name() + "> in spec())");
  return *std::static_pointer_cast<const Config>(set.build_config(values));
}
}  // namespace detail

}  // namespace kestrel
