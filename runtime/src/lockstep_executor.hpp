#pragma once
// The deterministic executor. Simulated time advances from one timer tick to the next; at each
// step every node runs in topological order and processes every message it received, in
// publication order. Messages on delayed connections arrive at the next step. Nothing depends on
// thread timing, so the same graph and seed give bit-identical outputs.
#include "progress.hpp"
#include "run_state.hpp"

namespace kestrel::detail {

class LockstepExecutor final : public Executor {
 public:
  explicit LockstepExecutor(RunState& run) : run_(run) {}

  void deliver(Edge& edge, const Envelope& envelope) override;
  Time now() const override { return now_; }

  /// Runs until the duration, the end of every source, or a stop. Returns the final sim time.
  Time run(Progress& progress);

 private:
  void enqueue(Edge& edge, const Envelope& envelope);
  void drain_inputs(NodeRuntime& node);
  void drop_undelivered();

  RunState& run_;
  Time now_{0};
  std::vector<std::pair<Edge*, Envelope>> delayed_;  // arrive at the next step
};

}  // namespace kestrel::detail
