#pragma once
// Private to the framework: the live objects of one run. A NodeRuntime wraps each node with its
// input slots, output edges and statistics; an Edge is one connection with its queue; RunState
// holds what all nodes share. The executors decide when nodes are called and how edges deliver.
#include <atomic>
#include <cmath>
#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "kestrel/node.hpp"
#include "kestrel/registry.hpp"
#include "kestrel/runtime/graph.hpp"
#include "kestrel/runtime/histogram.hpp"
#include "kestrel/runtime/run.hpp"

namespace kestrel::detail {

class NodeRuntime;

struct Edge {
  const ConnectionConfig* config = nullptr;
  NodeRuntime* from = nullptr;
  NodeRuntime* to = nullptr;
  int to_port = -1;
  int to_slot = -1;            // index into to->inputs: the port's slot, or a tap's extra slot
  std::deque<Envelope> queue;  // triggering inputs only
  std::uint64_t delivered = 0;
  std::uint64_t dropped = 0;
  std::size_t high_water = 0;

  /// Counts one message accepted by this connection (into its queue or its latest slot).
  void count_delivery();
  /// Appends to the queue of a triggering input and counts the delivery.
  void push(const Envelope& envelope);
  /// Discards every queued message, counting each as dropped.
  void drop_queued();
};

struct InputSlot {
  const PortSpec* spec = nullptr;
  Edge* edge = nullptr;      // null if the optional input is unconnected
  Envelope current;          // what Context::get returns during a call
  Envelope incoming_latest;  // realtime: newest value of a `latest` input, not yet seen
  bool triggers() const { return spec->trigger == Trigger::on_message; }
};

/// What the executor provides to nodes.
class Executor {
 public:
  virtual ~Executor() = default;
  virtual void deliver(Edge& edge, const Envelope& envelope) = 0;
  virtual Time now() const = 0;
};

class RunState;

class NodeRuntime {
 public:
  enum class Call { process, tick, finish };

  int index = -1;
  const NodeConfig* config = nullptr;
  std::unique_ptr<Node> node;
  std::unique_ptr<Logger> logger;
  std::mt19937_64 rng;
  double tick_interval_ns = 0.0;          // 0: no timer
  std::uint64_t ticks = 0;                // ticks done; the next one is due at tick_time(ticks)
  std::atomic<bool> source_ended{false};  // set by the node thread, read by the run loop
  std::vector<InputSlot> inputs;
  std::vector<std::vector<Edge*>> outputs;
  int current_trigger = -1;
  RunState* run = nullptr;

  // Statistics. Counters are atomic so the progress line can read them during a run.
  std::atomic<std::uint64_t> messages_in{0};
  std::atomic<std::uint64_t> messages_out{0};
  std::atomic<std::uint64_t> errors{0};
  std::atomic<std::uint64_t> calls{0};
  std::uint64_t skipped_ticks = 0;
  DurationHistogram processing;
  DurationHistogram latency;  // capture stamp to publication, of stamped messages

  // Realtime executor only: guards inputs and queues of this node.
  std::mutex mutex;
  std::condition_variable wake;   // a message arrived, or the run is stopping
  std::condition_variable space;  // a queue slot freed (for `block` producers)
  int upstream_alive = 0;         // producers on non-delayed edges that have not exited
  bool exited = false;

  const std::string& id() const { return config->id; }
  const std::string& type() const { return config->type->spec.type(); }
  bool has_triggering_input() const;
  bool has_timer() const { return tick_interval_ns > 0.0; }
  Time tick_time(std::uint64_t k) const {
    return Time(static_cast<std::int64_t>(std::llround(static_cast<double>(k) * tick_interval_ns)));
  }

  /// Calls the node, timing process() and tick(), and turning exceptions into run errors.
  /// Returns false if the node threw.
  bool call(Call what);

  /// The triggering input whose queue holds the oldest message (lowest sequence number), or -1
  /// if every queue is empty. Messages are processed in this order under both executors.
  int oldest_waiting_input() const;
  /// Moves the oldest message of input `input`'s queue into the slot Context::get reads, and
  /// makes it the trigger of the next process() call.
  void take_message(int input);
  /// Calls process() for the message taken with take_message(), then clears the trigger.
  bool process_taken();
  /// Calls tick() and counts it as done.
  void run_tick();

  void publish(std::string_view output, std::shared_ptr<const void> payload, std::string_view type,
               std::optional<Time> captured = std::nullopt);
};

class RunState {
 public:
  RunState(const GraphConfig& graph, const Registry& registry, const RunOptions& options);

  const GraphConfig& graph;
  const Registry& registry;
  const RunOptions& options;
  Report report;
  Executor* executor = nullptr;
  std::vector<std::unique_ptr<NodeRuntime>> nodes;
  std::vector<std::unique_ptr<Edge>> edges;
  std::vector<NodeRuntime*> order;  // topological

  std::atomic<std::uint64_t> next_sequence{1};
  std::atomic<bool> stop_requested{false};  // drain and end
  std::atomic<bool> end_requested{false};   // a node has ended the run: drain and complete
  std::atomic<bool> failed{false};          // a node error under on_error: stop

  /// Builds every node. Returns false (with errors recorded) if a constructor threw.
  bool instantiate();
  /// The run's length: the one in the options, else the graph's; none means until stopped.
  std::optional<double> duration_s() const;
  /// True once every node with a timer has called end_of_stream().
  bool all_sources_ended() const;
  /// Calls options.on_running the first time every source has been called (or has ended).
  void announce_when_running();
  /// True once the run should wind down: stop or end requested, failed, or an external stop flag.
  bool stopping() const;
  void node_error(NodeRuntime& node, const std::string& what);
  std::vector<std::string> errors() const;
  /// A node ends the run (Context::end_run): the first one's id and reason are kept.
  void end_run(const std::string& node, std::string_view why);
  /// {"node", "why"} of the node that ended the run; null when none did.
  nlohmann::json ended_by() const;

 private:
  bool announced_ = false;
  mutable std::mutex ended_by_mutex_;
  nlohmann::json ended_by_;
  mutable std::mutex errors_mutex_;
  std::vector<std::string> errors_;
};

}  // namespace kestrel::detail
