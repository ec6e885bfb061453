#pragma once
// Typed port handles. A node declares each port once, as a static constant, and uses the same
// constant in its NodeSpec and when it reads or publishes:
//
//   static constexpr kestrel::Input<msg::PointCloud> kCloud{"cloud"};
//   ...  spec.input(kCloud, "camera-frame points");
//   ...  auto cloud = ctx.get(kCloud);
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "kestrel/message.hpp"

namespace kestrel {

template <MessageType T>
struct Input {
  using type = T;
  std::string_view name;
  constexpr explicit Input(std::string_view port_name) : name(port_name) {}
};

template <MessageType T>
struct Output {
  using type = T;
  std::string_view name;
  constexpr explicit Output(std::string_view port_name) : name(port_name) {}
};

/// How a message arriving on an input affects its node.
enum class Trigger {
  on_message,  ///< each message calls process() once
  latest,      ///< the newest message is kept and read when something else triggers the node
};

struct InputOptions {
  Trigger trigger = Trigger::on_message;
  bool optional = false;  ///< may be left unconnected; get() then returns null
};

/// A tap: an input of any type that the graph builder connects to every output it selects, as
/// a recorder or a live view needs. Outputs are selected by their topic, "/NODE/PORT".
struct TapOptions {
  /// A string parameter of the node: topic patterns (fnmatch globs, `*` crosses '/'), separated by
  /// commas or spaces; a pattern starting with '!' takes topics out. Without a positive pattern
  /// the tap takes every output that is connected to something, except those of `skip_types`.
  std::string topics_param;
  std::vector<std::string> skip_types;  ///< message type names the default selection leaves out
};

/// A port as the registry, the validator and `kestrel inspect` see it.
struct PortSpec {
  std::string name;
  MessageInfo message;  ///< the message type: name ("*" accepts any type) and description
  std::string description;
  Trigger trigger = Trigger::on_message;
  bool optional = false;
  /// Set for a tap input (NodeSpec::tap), which takes any number of connections.
  std::optional<TapOptions> tap;

  /// The message type's name, as graphs and errors show it.
  const std::string& type() const { return message.name; }
};

}  // namespace kestrel
