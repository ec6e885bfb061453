#pragma once
// What a component's constructor gets: its name, its validated parameters (also as its config
// struct), a seed of its own, the logger of the node that owns it, and the means to build the
// components it is composed of in turn.
//
//   class GreedyAssociator final : public Associator {
//    public:
//     static ComponentSpec spec();                      // declares Config's parameters
//     explicit GreedyAssociator(const ComponentInit& init) : cfg_(init.config<Config>()) {}
//     ...
//   };
//   KESTREL_REGISTER_COMPONENT(Associator, GreedyAssociator)
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

#include "kestrel/config_spec.hpp"
#include "kestrel/logger.hpp"
#include "kestrel/param_spec.hpp"
#include "kestrel/params.hpp"

namespace kestrel {

class Registry;

namespace detail {
/// Builds the component named by `param_name` of an owner (a node or another component). The
/// component's seed is derived from the owner's seed and the parameter's name.
std::shared_ptr<void> make_component(const Registry& registry, const std::string& owner, const ParamSet& owner_spec,
                                     const Params& owner_params, const std::string& param_name, std::string_view kind,
                                     std::uint64_t owner_seed, Logger& log);
/// A seed for `name`, derived from `seed`: stable, and distinct between names.
std::uint64_t derive_seed(std::uint64_t seed, std::string_view name);
}  // namespace detail

/// What the constructors of nodes and components both get: a name, the validated parameters
/// (also as the config struct the spec binds them to), a seed of their own, a logger, and the
/// means to build the components they are composed of.
class InitBase {
 public:
  InitBase(std::string name, const ParamSet& spec, const Params& params, const Registry& registry, std::uint64_t seed,
           Logger& log)
      : name_(std::move(name)), spec_(spec), params_(params), registry_(registry), seed_(seed), log_(log) {}

  const Params& params() const { return params_; }
  /// The parameters as the config struct that the spec binds them to (see ConfigSpec).
  template <class Config>
  Config config() const {
    return detail::config_from<Config>(spec_, params_, "'" + name_ + "'");
  }
  /// One parameter that is not bound to a config struct (declared with spec's param()).
  template <class T>
  T param(const std::string& name) const {
    return params_.get<T>(name);
  }
  /// A seed derived from the run's seed and this node's id (for a component: from its node's seed
  /// and its parameter's name): stable across runs, distinct between nodes and components.
  std::uint64_t seed() const { return seed_; }
  Logger& log() const { return log_; }

  /// Builds the component named by component parameter `param_name`. Interface must declare
  /// `static constexpr std::string_view kKind` matching the parameter's kind.
  template <class Interface>
  std::shared_ptr<Interface> make_component(const std::string& param_name) const {
    return std::static_pointer_cast<Interface>(
        detail::make_component(registry_, name_, spec_, params_, param_name, Interface::kKind, seed_, log_));
  }

 protected:
  const std::string& name() const { return name_; }

 private:
  std::string name_;
  const ParamSet& spec_;
  const Params& params_;
  const Registry& registry_;
  std::uint64_t seed_;
  Logger& log_;
};

class ComponentInit : public InitBase {
 public:
  using InitBase::InitBase;
  /// Where the component sits: "<node id>.<parameter>", e.g. "tracker.associator".
  const std::string& name() const { return InitBase::name(); }
};

}  // namespace kestrel
