#pragma once
// The wall-clock executor: every node runs on its own thread. Each triggering input has a
// bounded queue with the connection's policy (latest, fifo N, block N), and every message a
// queue discards is counted. On stop, sources stop first, then each node drains its queues
// before it exits, in upstream-to-downstream order, and finally every node's finish() runs.
#include <thread>

#include "progress.hpp"
#include "run_state.hpp"

namespace kestrel::detail {

class RealtimeExecutor final : public Executor {
 public:
  explicit RealtimeExecutor(RunState& run) : run_(run) {}

  void deliver(Edge& edge, const Envelope& envelope) override;
  Time now() const override { return std::chrono::steady_clock::now() - start_; }

  /// Runs until the duration, the end of every source, or a stop. Returns the run time.
  Time run(Progress& progress);

 private:
  void node_loop(NodeRuntime& node);
  void wake_all();

  RunState& run_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::atomic<bool> stopping_{false};  // sources stop; queues drain
  std::atomic<bool> aborting_{false};  // a node failed: stop at once
};

}  // namespace kestrel::detail
