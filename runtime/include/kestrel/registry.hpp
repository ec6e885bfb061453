#pragma once
// The registry of everything plugins provide: node types, components and message types.
// Plugins add to it when they are loaded; graphs, `kestrel plugins` and `kestrel inspect` read it.
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "kestrel/message.hpp"
#include "kestrel/node.hpp"
#include "kestrel/node_spec.hpp"

namespace kestrel {

using NodeFactory = std::function<std::unique_ptr<Node>(NodeInit&)>;
/// Returns the component as a pointer to its interface type, erased to void.
using ComponentFactory = std::function<std::shared_ptr<void>(const ComponentInit&)>;

struct NodeType {
  NodeSpec spec;
  NodeFactory factory;
  std::string plugin;  ///< file of the plugin that registered it ("" for the framework)
};

struct ComponentType {
  std::string kind;
  ComponentSpec spec;
  ComponentFactory factory;
  std::string plugin;
};

struct MessageTypeEntry {
  MessageInfo info;
  std::string plugin;
};

class Registry {
 public:
  /// Knows only the wildcard message type: every other type comes with the plugins that use it.
  Registry();

  /// Registers a node type and the message types of its ports. Throws kestrel::Error if the
  /// type name is taken (naming both plugins) or if its spec is malformed (see check_param_set).
  void add_node(NodeSpec spec, NodeFactory factory);
  /// The same for a component of `kind`.
  void add_component(std::string kind, ComponentSpec spec, ComponentFactory factory);
  /// Registering the same message name twice is allowed (plugins share headers); the first wins.
  void add_message(MessageInfo info);
  template <MessageType T>
  void add_message() {
    add_message(message_info<T>());
  }

  const NodeType* find_node(std::string_view type) const;
  const ComponentType* find_component(std::string_view kind, std::string_view name) const;
  const MessageTypeEntry* find_message(std::string_view name) const;

  const std::map<std::string, NodeType, std::less<>>& nodes() const { return nodes_; }
  /// Keyed by "kind/name".
  const std::map<std::string, ComponentType, std::less<>>& components() const { return components_; }
  const std::map<std::string, MessageTypeEntry, std::less<>>& messages() const { return messages_; }

  std::vector<std::string> node_type_names() const;
  std::vector<std::string> component_names(std::string_view kind) const;

  /// The plugin file whose registrations follow; set by the plugin loader.
  void set_current_plugin(std::string file) { current_plugin_ = std::move(file); }

 private:
  std::map<std::string, NodeType, std::less<>> nodes_;
  std::map<std::string, ComponentType, std::less<>> components_;
  std::map<std::string, MessageTypeEntry, std::less<>> messages_;
  std::string current_plugin_;
};

}  // namespace kestrel
