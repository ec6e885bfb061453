#pragma once
// A graph: nodes, their parameters and the connections between their ports, read from YAML and
// validated against the registry. build_graph() is the only way to get a GraphConfig, so a
// GraphConfig is always valid: every type exists, every parameter checks, every port matches,
// every required input is connected and every cycle is broken by a delayed connection.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "kestrel/params.hpp"
#include "kestrel/registry.hpp"
#include "kestrel/runtime/diagnostics.hpp"

namespace kestrel {

enum class ExecutorKind { lockstep, realtime };
enum class ClockKind { simulated, wall };
enum class ErrorPolicy { stop, skip };

/// What an input queue does when it is full (realtime executor; lockstep never drops).
struct QueuePolicy {
  enum class Kind { latest, fifo, block };
  Kind kind = Kind::fifo;
  std::size_t capacity = 16;

  /// "latest", "fifo 16" or "block 1"
  std::string str() const;
  /// Parses "latest", "fifo N", "block" or "block N". Returns nullopt on a malformed policy.
  static std::optional<QueuePolicy> parse(const std::string& text);
  /// The forms parse() accepts, for error messages.
  static constexpr const char* kForms = "expected 'latest', 'fifo N' or 'block N'";
};

struct NodeConfig {
  std::string id;
  const NodeType* type = nullptr;
  Params params;
  SourceLocation where;
};

struct ConnectionConfig {
  int from_node = -1;  ///< index into GraphConfig::nodes
  int from_port = -1;  ///< index into the source's outputs
  int to_node = -1;
  int to_port = -1;  ///< index into the destination's inputs
  QueuePolicy policy;
  bool delayed = false;
  SourceLocation where;
  std::string label;  ///< "camera.frame -> depth.frame"
};

struct GraphConfig {
  std::filesystem::path file;
  std::string name;
  std::string description;
  ExecutorKind executor = ExecutorKind::lockstep;
  ClockKind clock = ClockKind::simulated;
  double real_time_factor = 1.0;  ///< lockstep with a wall clock: sim seconds per wall second
  std::uint64_t seed = 0;
  ErrorPolicy on_error = ErrorPolicy::stop;
  std::optional<double> duration_s;                 ///< run length; sim seconds (lockstep) or wall seconds
  std::vector<std::filesystem::path> plugin_paths;  ///< resolved against the graph's folder
  std::vector<NodeConfig> nodes;
  std::vector<ConnectionConfig> connections;
  /// Node indices in an order where every non-delayed connection goes forward.
  std::vector<int> topological_order;
};

/// The YAML text of a graph, parsed but not yet validated.
class GraphSource {
 public:
  static GraphSource from_file(const std::filesystem::path& file);
  static GraphSource from_string(const std::string& yaml, const std::string& label = "<string>");
  ~GraphSource();
  GraphSource(GraphSource&&) noexcept;
  GraphSource& operator=(GraphSource&&) noexcept;

  /// The graph's plugin_paths, resolved against its folder (needed before the registry exists).
  std::vector<std::filesystem::path> plugin_paths() const;
  /// Errors from reading or parsing the file; build_graph() repeats them.
  const Diagnostics& read_errors() const;
  const std::string& label() const;

  struct Impl;
  const Impl& impl() const { return *impl_; }

 private:
  explicit GraphSource(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

struct BuildResult {
  std::optional<GraphConfig> graph;  ///< set only if there are no errors
  Diagnostics diagnostics;
};

/// Validates `source` against `registry`. Each override is "node.param=value" (the value is
/// parsed as YAML) and is checked like the file's own values. Each fragment (a map with `nodes`
/// and `connections` only, such as the recorder `kestrel run --record` adds) joins the graph as
/// an included file would; its errors carry its label. `executor`, when set, replaces the
/// graph's executor (and its clock: wall for realtime, simulated for lockstep) before the nodes
/// are checked against what they need of it (NodeSpec::needs_executor).
BuildResult build_graph(const GraphSource& source, const Registry& registry,
                        const std::vector<std::string>& overrides = {},
                        const std::vector<const GraphSource*>& fragments = {},
                        std::optional<ExecutorKind> executor = {});

/// A part's interface (docs/graph-format.md, "Parts"), as `kestrel inspect FILE` prints it.
struct PartInfo {
  struct Port {
    std::string name, type, description;  ///< type: declared, or the bound node port's ("" if neither is known)
    std::vector<std::string> bound;       ///< the node ports it is ("node.port")
  };
  struct Arg {
    std::string name, default_value, unit, description;  ///< default_value: YAML text, "" if required
    std::vector<std::string> bound;                      ///< the parameters it sets ("node.param")
  };
  std::string name, description;
  std::vector<Port> inputs, outputs;
  std::vector<Arg> args;
};

/// The interface `source` declares, if its file is a part; its malformed declarations go in
/// `diagnostics`. Port types not declared are read from the node types in `registry`.
std::optional<PartInfo> part_info(const GraphSource& source, const Registry& registry, Diagnostics& diagnostics);

/// The graph in Graphviz dot.
std::string to_dot(const GraphConfig& graph);

}  // namespace kestrel
