#pragma once
// The single declaration of a node type: what it is called, what it does, its typed ports and
// its parameters. Built by the node class's static spec() function.
#include <optional>
#include <string>
#include <vector>

#include "kestrel/param_spec.hpp"
#include "kestrel/ports.hpp"

namespace kestrel {

class NodeSpec {
 public:
  /// `type` is the name graphs use (snake_case, unique across plugins); `summary` is the one
  /// line `kestrel plugins` prints.
  NodeSpec(std::string type, std::string summary) : type_(std::move(type)), summary_(std::move(summary)) {}

  template <MessageType T>
  NodeSpec& input(const Input<T>& port, std::string description, InputOptions options = {}) {
    inputs_.push_back(PortSpec{std::string(port.name), std::string(MessageTraits<T>::name), std::move(description),
                               options.trigger, options.optional});
    return *this;
  }

  template <MessageType T>
  NodeSpec& output(const Output<T>& port, std::string description) {
    outputs_.push_back(PortSpec{std::string(port.name), std::string(MessageTraits<T>::name), std::move(description),
                                Trigger::on_message, false});
    return *this;
  }

  NodeSpec& param(ParamSpec spec) {
    params_.push_back(std::move(spec));
    return *this;
  }

  /// Longer documentation shown by `kestrel inspect`.
  NodeSpec& details(std::string text) {
    details_ = std::move(text);
    return *this;
  }

  const std::string& type() const { return type_; }
  const std::string& summary() const { return summary_; }
  const std::string& details() const { return details_; }
  const std::vector<PortSpec>& inputs() const { return inputs_; }
  const std::vector<PortSpec>& outputs() const { return outputs_; }
  const std::vector<ParamSpec>& params() const { return params_; }

  /// Index of the named port, or -1.
  int input_index(std::string_view name) const;
  int output_index(std::string_view name) const;
  const ParamSpec* find_param(std::string_view name) const;

 private:
  std::string type_;
  std::string summary_;
  std::string details_;
  std::vector<PortSpec> inputs_;
  std::vector<PortSpec> outputs_;
  std::vector<ParamSpec> params_;
};

/// The declaration of a component: a strategy of some `kind` (e.g. "associator") that a node
/// builds by name from one of its parameters.
class ComponentSpec {
 public:
  ComponentSpec(std::string name, std::string summary) : name_(std::move(name)), summary_(std::move(summary)) {}

  ComponentSpec& param(ParamSpec spec) {
    params_.push_back(std::move(spec));
    return *this;
  }
  ComponentSpec& details(std::string text) {
    details_ = std::move(text);
    return *this;
  }

  const std::string& name() const { return name_; }
  const std::string& summary() const { return summary_; }
  const std::string& details() const { return details_; }
  const std::vector<ParamSpec>& params() const { return params_; }
  const ParamSpec* find_param(std::string_view name) const;

 private:
  std::string name_;
  std::string summary_;
  std::string details_;
  std::vector<ParamSpec> params_;
};

}  // namespace kestrel
