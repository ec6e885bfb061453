#include "realtime_executor.hpp"

#include <limits>

namespace kestrel::detail {

namespace {

// Moves the newest value of each `latest` input into the slot the node reads. Caller holds the
// node's mutex.
void refresh_latest_inputs(NodeRuntime& node) {
  for (auto& slot : node.inputs)
    if (!slot.triggers() && slot.incoming_latest) slot.current = std::move(slot.incoming_latest);
}

int oldest_waiting_input(const NodeRuntime& node) {
  int next = -1;
  std::uint64_t oldest = std::numeric_limits<std::uint64_t>::max();
  for (std::size_t i = 0; i < node.inputs.size(); ++i) {
    const Edge* e = node.inputs[i].edge;
    if (e && node.inputs[i].triggers() && !e->queue.empty() && e->queue.front().sequence < oldest) {
      oldest = e->queue.front().sequence;
      next = static_cast<int>(i);
    }
  }
  return next;
}

}  // namespace

void RealtimeExecutor::deliver(Edge& edge, const Envelope& envelope) {
  NodeRuntime& to = *edge.to;
  InputSlot& slot = to.inputs[static_cast<std::size_t>(edge.to_port)];
  std::unique_lock lock(to.mutex);
  if (to.exited) {
    ++edge.dropped;
    return;
  }
  if (!slot.triggers()) {
    slot.incoming_latest = envelope;
    ++edge.delivered;
    to.messages_in.fetch_add(1, std::memory_order_relaxed);
    return;
  }
  const QueuePolicy& policy = edge.config->policy;
  switch (policy.kind) {
    case QueuePolicy::Kind::latest:
      edge.dropped += edge.queue.size();
      edge.queue.clear();
      break;
    case QueuePolicy::Kind::fifo:
      while (edge.queue.size() >= policy.capacity) {
        edge.queue.pop_front();
        ++edge.dropped;
      }
      break;
    case QueuePolicy::Kind::block:
      to.space.wait(lock, [&] { return edge.queue.size() < policy.capacity || to.exited || aborting_ || run_.failed; });
      if (to.exited || aborting_ || run_.failed) {
        ++edge.dropped;
        return;
      }
      break;
  }
  edge.queue.push_back(envelope);
  edge.note_queue_size();
  ++edge.delivered;
  to.messages_in.fetch_add(1, std::memory_order_relaxed);
  lock.unlock();
  to.wake.notify_one();
}

void RealtimeExecutor::node_loop(NodeRuntime& node) {
  const bool has_timer = node.has_timer();
  const bool has_triggers = node.has_triggering_input();
  std::unique_lock lock(node.mutex);
  while (!aborting_ && !run_.failed) {
    if (const int next = oldest_waiting_input(node); next >= 0) {
      InputSlot& slot = node.inputs[static_cast<std::size_t>(next)];
      slot.current = std::move(slot.edge->queue.front());
      slot.edge->queue.pop_front();
      refresh_latest_inputs(node);
      node.current_trigger = next;
      lock.unlock();
      node.space.notify_all();
      node.call(NodeRuntime::Call::process);
      lock.lock();
      node.current_trigger = -1;
      continue;
    }
    const bool ticking = has_timer && !node.source_ended && !stopping_;
    if (!ticking) {
      if (stopping_ && node.upstream_alive == 0) break;
      if (has_timer && node.source_ended && !has_triggers) break;
      node.wake.wait(lock);
      continue;
    }
    const auto next_tick = start_ + node.tick_time(node.ticks);
    if (std::chrono::steady_clock::now() < next_tick) {
      node.wake.wait_until(lock, next_tick);
      continue;
    }
    refresh_latest_inputs(node);
    lock.unlock();
    node.call(NodeRuntime::Call::tick);
    lock.lock();
    ++node.ticks;
    // A node that runs late skips the ticks it missed instead of bursting to catch up.
    const auto late = std::chrono::steady_clock::now() - start_;
    while (node.tick_time(node.ticks) < late) {
      ++node.ticks;
      ++node.skipped_ticks;
    }
  }
  node.exited = true;
  for (auto& slot : node.inputs) {
    if (!slot.edge) continue;
    slot.edge->dropped += slot.edge->queue.size();
    slot.edge->queue.clear();
  }
  lock.unlock();
  node.space.notify_all();
  for (auto& port : node.outputs) {
    for (Edge* edge : port) {
      if (edge->config->delayed) continue;
      {
        std::lock_guard downstream(edge->to->mutex);
        --edge->to->upstream_alive;
      }
      edge->to->wake.notify_all();
    }
  }
}

bool RealtimeExecutor::all_sources_ended() const {
  for (const auto& node : run_.nodes)
    if (node->has_timer() && !node->source_ended) return false;
  return true;
}

void RealtimeExecutor::wake_all() {
  for (auto& node : run_.nodes) {
    { std::lock_guard lock(node->mutex); }
    node->wake.notify_all();
    node->space.notify_all();
  }
}

Time RealtimeExecutor::run(Progress& progress) {
  const std::optional<double> duration = run_.options.duration_s ? run_.options.duration_s : run_.graph.duration_s;
  for (const auto& edge : run_.edges)
    if (!edge->config->delayed) ++edge->to->upstream_alive;

  start_ = std::chrono::steady_clock::now();
  std::vector<std::thread> threads;
  threads.reserve(run_.nodes.size());
  for (auto& node : run_.nodes) threads.emplace_back([this, n = node.get()] { node_loop(*n); });

  while (!run_.stopping() && !all_sources_ended()) {
    if (duration && to_seconds(now()) >= *duration) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    progress.update(now());
  }
  const Time stopped_at = now();
  if (run_.failed)
    aborting_ = true;
  else
    stopping_ = true;
  wake_all();
  for (auto& t : threads) t.join();
  return stopped_at;
}

}  // namespace kestrel::detail
