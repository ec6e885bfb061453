#include "lockstep_executor.hpp"

#include <thread>

namespace kestrel::detail {

void LockstepExecutor::deliver(Edge& edge, const Envelope& envelope) {
  if (edge.config->delayed)
    delayed_.emplace_back(&edge, envelope);
  else
    enqueue(edge, envelope);
}

void LockstepExecutor::enqueue(Edge& edge, const Envelope& envelope) {
  InputSlot& slot = edge.to->inputs[static_cast<std::size_t>(edge.to_slot)];
  if (slot.triggers()) {
    edge.push(envelope);
  } else {
    slot.current = envelope;
    edge.count_delivery();
  }
}

void LockstepExecutor::drain_inputs(NodeRuntime& node) {
  // The oldest waiting message across all triggering inputs goes first.
  for (int next = node.oldest_waiting_input(); next >= 0 && !run_.failed; next = node.oldest_waiting_input()) {
    node.take_message(next);
    node.process_taken();
  }
}

void LockstepExecutor::drop_undelivered() {
  for (auto& [edge, _] : delayed_) ++edge->dropped;
  delayed_.clear();
  for (auto& edge : run_.edges) edge->drop_queued();
}

Time LockstepExecutor::run(Progress& progress) {
  const auto& graph = run_.graph;
  const std::optional<double> duration = run_.duration_s();
  const Time end = duration ? from_seconds(*duration) : Time::max();
  const bool paced = graph.clock == ClockKind::wall;
  const auto wall_start = std::chrono::steady_clock::now();

  bool first_step = true;
  while (!run_.stopping()) {
    Time step = Time::max();
    for (auto* node : run_.order)
      if (node->has_timer() && !node->source_ended) step = std::min(step, node->tick_time(node->ticks));
    if (step == Time::max()) {
      if (delayed_.empty()) break;  // every source has ended and nothing is in flight
      step = now_;                  // flush the feedback still in flight
    }
    if (step >= end) break;
    now_ = first_step ? step : std::max(step, now_);
    first_step = false;

    if (paced) {
      const auto wall_due = wall_start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                             std::chrono::duration<double>(to_seconds(now_) / graph.real_time_factor));
      std::this_thread::sleep_until(wall_due);
    }

    auto arriving = std::move(delayed_);
    delayed_.clear();
    for (auto& [edge, envelope] : arriving) enqueue(*edge, envelope);

    for (NodeRuntime* node : run_.order) {
      if (node->has_timer() && !node->source_ended && node->tick_time(node->ticks) == now_) {
        node->run_tick();
      }
      drain_inputs(*node);
      if (run_.failed) break;
    }
    run_.announce_when_running();
    progress.update(now_);
  }
  drop_undelivered();
  return now_;
}

}  // namespace kestrel::detail
