#include "lockstep_executor.hpp"

#include <limits>
#include <thread>

namespace kestrel::detail {

void LockstepExecutor::deliver(Edge& edge, const Envelope& envelope) {
  if (edge.config->delayed)
    delayed_.emplace_back(&edge, envelope);
  else
    enqueue(edge, envelope);
}

void LockstepExecutor::enqueue(Edge& edge, const Envelope& envelope) {
  InputSlot& slot = edge.to->inputs[static_cast<std::size_t>(edge.to_port)];
  ++edge.delivered;
  edge.to->messages_in.fetch_add(1, std::memory_order_relaxed);
  if (slot.triggers()) {
    edge.queue.push_back(envelope);
    edge.note_queue_size();
  } else {
    slot.current = envelope;
  }
}

void LockstepExecutor::drain_inputs(NodeRuntime& node) {
  for (;;) {
    // The oldest waiting message across all triggering inputs goes first.
    int next = -1;
    std::uint64_t oldest = std::numeric_limits<std::uint64_t>::max();
    for (std::size_t i = 0; i < node.inputs.size(); ++i) {
      const Edge* e = node.inputs[i].edge;
      if (e && !e->queue.empty() && e->queue.front().sequence < oldest) {
        oldest = e->queue.front().sequence;
        next = static_cast<int>(i);
      }
    }
    if (next < 0 || run_.failed) return;
    InputSlot& slot = node.inputs[static_cast<std::size_t>(next)];
    slot.current = std::move(slot.edge->queue.front());
    slot.edge->queue.pop_front();
    node.current_trigger = next;
    node.call(NodeRuntime::Call::process);
    node.current_trigger = -1;
  }
}

void LockstepExecutor::drop_undelivered() {
  for (auto& [edge, _] : delayed_) ++edge->dropped;
  delayed_.clear();
  for (auto& edge : run_.edges) {
    edge->dropped += edge->queue.size();
    edge->queue.clear();
  }
}

Time LockstepExecutor::run(Progress& progress) {
  const auto& graph = run_.graph;
  const std::optional<double> duration = run_.options.duration_s ? run_.options.duration_s : graph.duration_s;
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
        node->call(NodeRuntime::Call::tick);
        ++node->ticks;
      }
      drain_inputs(*node);
      if (run_.failed) break;
    }
    progress.update(now_);
  }
  drop_undelivered();
  return now_;
}

}  // namespace kestrel::detail
