#pragma once
// The single declaration of a node type: what it is called, what it does, its typed ports and
// its parameters. Built by the node class's static spec() function.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "kestrel/config_spec.hpp"
#include "kestrel/param_spec.hpp"
#include "kestrel/params.hpp"
#include "kestrel/ports.hpp"

namespace kestrel {

/// The executor a node type can run under. A node that talks to a real link or device needs the
/// realtime executor (nothing waits for a lockstep step there); a node whose results only make
/// sense step by step may need lockstep. `kestrel validate` refuses a graph that runs its nodes
/// under the other one.
enum class ExecutorNeed { any, realtime, lockstep };

/// What NodeSpec and ComponentSpec share: a name, a summary, longer details and the parameters.
template <class Self>
class SpecBase {
 public:
  /// A parameter that is not bound to a config field (read with Params::get).
  Self& param(ParamSpec spec) {
    params_.params.push_back(std::move(spec));
    return self();
  }
  /// The parameters bound to the fields of `Config`, with their rules. Once per spec.
  template <class Config>
  Self& config(ConfigSpec<Config> spec) {
    ParamSet set = std::move(spec).release();
    for (auto& p : set.params) params_.params.push_back(std::move(p));
    for (auto& r : set.rules) params_.rules.push_back(std::move(r));
    params_.make_config = std::move(set.make_config);
    params_.config_type = set.config_type;
    return self();
  }
  /// Longer documentation shown by `kestrel inspect`.
  Self& details(std::string text) {
    details_ = std::move(text);
    return self();
  }

  const std::string& summary() const { return summary_; }
  const std::string& details() const { return details_; }
  const std::vector<ParamSpec>& params() const { return params_.params; }
  const std::vector<ParamRule>& rules() const { return params_.rules; }
  const ParamSet& param_set() const { return params_; }
  const ParamSpec* find_param(std::string_view name) const { return params_.find(name); }

 protected:
  explicit SpecBase(std::string summary) : summary_(std::move(summary)) {}

 private:
  Self& self() { return static_cast<Self&>(*this); }
  std::string summary_;
  std::string details_;
  ParamSet params_;
};

class NodeSpec : public SpecBase<NodeSpec> {
 public:
  /// `type` is the name graphs use (snake_case, unique across plugins); `summary` is the one
  /// line `kestrel plugins` prints.
  NodeSpec(std::string type, std::string summary) : SpecBase(std::move(summary)), type_(std::move(type)) {}

  template <MessageType T>
  NodeSpec& input(const Input<T>& port, std::string description, InputOptions options = {}) {
    inputs_.push_back(PortSpec{std::string(port.name), message_info<T>(), std::move(description), options.trigger,
                               options.optional, std::nullopt});
    return *this;
  }

  /// A tap input (TapOptions): the builder connects it to every output its topic parameter
  /// selects, and a graph may connect more outputs to it by hand. Envelope::source_node and
  /// source_port say where each message came from.
  NodeSpec& tap(const Input<AnyMessage>& port, std::string description, TapOptions options) {
    PortSpec spec{std::string(port.name),
                  message_info<AnyMessage>(),
                  std::move(description),
                  Trigger::on_message,
                  true,
                  std::nullopt};
    spec.tap = std::move(options);
    inputs_.push_back(std::move(spec));
    return *this;
  }
  template <MessageType T>
  NodeSpec& output(const Output<T>& port, std::string description) {
    outputs_.push_back(PortSpec{std::string(port.name), message_info<T>(), std::move(description), Trigger::on_message,
                                false, std::nullopt});
    return *this;
  }

  /// The executor the node needs, and why ("it talks to a real link"), for the error that refuses
  /// a graph running it under the other one.
  NodeSpec& needs_executor(ExecutorNeed need, std::string reason) {
    executor_need_ = need;
    executor_reason_ = std::move(reason);
    return *this;
  }

  /// The same, only when `applies` holds of the node's parameters (a bridge that subscribes to a
  /// live bus needs the realtime executor; one that only publishes does not).
  NodeSpec& needs_executor_when(ExecutorNeed need, std::string reason, std::function<bool(const Params&)> applies) {
    needs_executor(need, std::move(reason));
    executor_applies_ = std::move(applies);
    return *this;
  }

  const std::string& type() const { return type_; }
  /// The executor a node of this type with `params` needs.
  ExecutorNeed executor_need(const Params& params) const {
    return executor_applies_ && !executor_applies_(params) ? ExecutorNeed::any : executor_need_;
  }
  ExecutorNeed executor_need() const { return executor_need_; }
  const std::string& executor_reason() const { return executor_reason_; }
  const std::vector<PortSpec>& inputs() const { return inputs_; }
  const std::vector<PortSpec>& outputs() const { return outputs_; }

  /// Index of the named port, or -1.
  int input_index(std::string_view name) const;
  int output_index(std::string_view name) const;

 private:
  std::string type_;
  ExecutorNeed executor_need_ = ExecutorNeed::any;
  std::string executor_reason_;
  std::function<bool(const Params&)> executor_applies_;
  std::vector<PortSpec> inputs_;
  std::vector<PortSpec> outputs_;
};

/// The declaration of a component: a strategy of some `kind` (e.g. "associator") that a node
/// builds by name from one of its parameters.
class ComponentSpec : public SpecBase<ComponentSpec> {
 public:
  ComponentSpec(std::string name, std::string summary) : SpecBase(std::move(summary)), name_(std::move(name)) {}
  const std::string& name() const { return name_; }

 private:
  std::string name_;
};

}  // namespace kestrel
