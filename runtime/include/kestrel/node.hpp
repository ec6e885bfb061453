#pragma once
// What a plugin author implements: a Node, built from a NodeInit, called with a Context.
//
//   struct DoublerConfig {
//     double factor = 2.0;
//   };
//   class Doubler final : public kestrel::Node {
//    public:
//     static constexpr kestrel::Input<Number> kIn{"in"};
//     static constexpr kestrel::Output<Number> kOut{"out"};
//     static kestrel::NodeSpec spec() {
//       kestrel::ConfigSpec<DoublerConfig> c;
//       c.param("factor", &DoublerConfig::factor).range(-10.0, 10.0).describe("multiplier");
//       return kestrel::NodeSpec("doubler", "Multiplies each number by a factor")
//           .input(kIn, "numbers").output(kOut, "scaled numbers")
//           .config(std::move(c));
//     }
//     explicit Doubler(kestrel::NodeInit& init) : cfg_(init.config<DoublerConfig>()) {}
//     void process(kestrel::Context& ctx) override {
//       auto in = ctx.get(kIn);
//       ctx.publish(kOut, Number{in->stamp, in->value * cfg_.factor});
//     }
//    private:
//     DoublerConfig cfg_;
//   };
//   KESTREL_REGISTER_NODE(Doubler)
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <string_view>

#include "kestrel/component.hpp"
#include "kestrel/error.hpp"
#include "kestrel/logger.hpp"
#include "kestrel/message.hpp"
#include "kestrel/node_spec.hpp"
#include "kestrel/params.hpp"
#include "kestrel/ports.hpp"
#include "kestrel/report.hpp"
#include "kestrel/time.hpp"

namespace kestrel {

namespace detail {
class NodeRuntime;
}
class Registry;

/// Everything an executor calls on a node. All calls for one node come from one thread at a
/// time, so a node needs no locking of its own state.
class Node {
 public:
  virtual ~Node() = default;

  /// Called once per message on a triggering input (see InputOptions::trigger).
  virtual void process(class Context& ctx);
  /// Called at the rate set with NodeInit::set_rate (or set_period), starting at time zero.
  virtual void tick(class Context& ctx);
  /// Called once at the end of the run, after every input has drained: flush files, add to the
  /// report. Still called after a node error stopped the run.
  virtual void finish(class Context& ctx);
};

/// What a node's constructor gets: its identity, its validated parameters, and the means to
/// build its components and to ask for a timer.
class NodeInit : public InitBase {
 public:
  NodeInit(std::string id, const NodeSpec& spec, const Params& params, const Registry& registry, std::uint64_t seed,
           Logger& log, bool realtime = false)
      : InitBase(id, spec.param_set(), params, registry, seed, log), spec_(spec), realtime_(realtime) {}

  const std::string& id() const { return name(); }
  const NodeSpec& spec() const { return spec_; }

  /// Asks for tick() `hz` times a second, from time zero. Sources use this. Tick k falls at
  /// round(k / hz) on the run clock, so 30 Hz gives exactly 600 ticks in 20 s.
  void set_rate(double hz);
  /// Asks for tick() every `period`, from time zero.
  void set_period(Duration period);
  /// Nanoseconds between ticks; 0 if the node has no timer.
  double tick_interval_ns() const { return tick_interval_ns_; }
  /// True under the realtime executor, where a node that does slow I/O (a recorder) must not
  /// hold up the graph; false under lockstep, where every call is part of a reproducible step.
  bool realtime() const { return realtime_; }

 private:
  const NodeSpec& spec_;
  bool realtime_ = false;
  double tick_interval_ns_ = 0.0;
};

/// A node's view of the run while it processes a message or a tick.
class Context {
 public:
  explicit Context(detail::NodeRuntime& runtime) : rt_(runtime) {}

  /// The message on `port`: the one that triggered this call, or the newest one received.
  /// Null if nothing has arrived yet (or the optional input is unconnected).
  template <MessageType T>
  std::shared_ptr<const T> get(const Input<T>& port) const {
    return std::static_pointer_cast<const T>(envelope(port.name).payload);
  }
  /// The envelope on an input: payload, type name, publish time and sequence number.
  const Envelope& envelope(std::string_view input) const;

  /// True if this call was triggered by a message on `port`.
  template <MessageType T>
  bool triggered_by(const Input<T>& port) const {
    return trigger() == port.name;
  }
  /// Name of the input whose message triggered this call; empty for tick() and finish().
  std::string_view trigger() const;

  /// Messages with a `stamp` (capture time, see docs/messages.md) also count towards the node's
  /// latency since capture in `--stats`.
  template <MessageType T>
  void publish(const Output<T>& port, std::shared_ptr<const T> message) {
    std::optional<Time> captured;
    if constexpr (requires(const T& m) {
                    { m.stamp } -> std::convertible_to<Time>;
                  })
      if (message) captured = message->stamp;
    publish_erased(port.name, std::shared_ptr<const void>(std::move(message)), MessageTraits<T>::name, captured);
  }
  template <MessageType T>
  void publish(const Output<T>& port, T message) {
    publish(port, std::make_shared<const T>(std::move(message)));
  }

  /// Now, on the run's clock.
  Time now() const;
  const std::string& id() const;
  Logger& log();
  /// This node's random generator, seeded from NodeInit::seed(). Use it, not a private one, so
  /// that lockstep runs reproduce.
  std::mt19937_64& rng();
  /// Sets the run report's section `key`, owned by this node from then on: its values, the unit
  /// and direction of each metric in it (sweep, ab and plot compare runs with them), its text.
  void set_report_section(const std::string& key, const ReportSection& section);
  /// What is running, as report.json's `kestrel_version` and `graph` record it: {"kestrel_version",
  /// "graph": {"file", "name", "executor", "clock", "seed", "duration_s", "resolved"}}.
  nlohmann::json run_description() const;
  /// True when the run keeps a report folder, so that artifacts are worth preparing.
  bool keeps_artifacts() const;
  /// Adds a file to the run report (a PNG is shown in report.md): the runtime writes it, checks
  /// the write and lists it. Ignored when the run keeps no report folder.
  void add_artifact(const std::string& file_name, std::string_view bytes, std::string caption = {});

  /// A source says it has nothing more to publish; it gets no more ticks. The run ends when every
  /// source has ended (or at its duration).
  void end_of_stream();
  /// Ends the whole run cleanly, as a signal would.
  void request_stop();
  /// Ends the whole run here, as reaching its duration would: every node finishes, the outcome is
  /// `completed`, and the report's `ended_by` gives this node's id and `why`. For a node that
  /// knows the run has nothing more to show (an engagement decided). The first call counts.
  void end_run(std::string_view why);

 private:
  void publish_erased(std::string_view output, std::shared_ptr<const void> payload, std::string_view type,
                      std::optional<Time> captured);
  detail::NodeRuntime& rt_;
};

}  // namespace kestrel
