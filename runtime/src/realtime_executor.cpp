#include "realtime_executor.hpp"

namespace kestrel::detail {

namespace {

// Moves the newest value of each `latest` input into the slot the node reads. Caller holds the
// node's mutex.
void refresh_latest_inputs(NodeRuntime& node) {
  for (auto& slot : node.inputs)
    if (!slot.triggers() && slot.incoming_latest) slot.current = std::move(slot.incoming_latest);
}

}  // namespace

void RealtimeExecutor::deliver(Edge& edge, const Envelope& envelope) {
  NodeRuntime& to = *edge.to;
  InputSlot& slot = to.inputs[static_cast<std::size_t>(edge.to_slot)];
  std::unique_lock lock(to.mutex);
  if (to.exited) {
    ++edge.dropped;
    return;
  }
  if (!slot.triggers()) {
    slot.incoming_latest = envelope;
    edge.count_delivery();
    return;
  }
  const QueuePolicy& policy = edge.config->policy;
  switch (policy.kind) {
    case QueuePolicy::Kind::latest:
      edge.drop_queued();
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
  edge.push(envelope);
  lock.unlock();
  to.wake.notify_one();
}

void RealtimeExecutor::node_loop(NodeRuntime& node) {
  const bool has_timer = node.has_timer();
  const bool has_triggers = node.has_triggering_input();
  std::unique_lock lock(node.mutex);
  while (!aborting_ && !run_.failed) {
    if (const int next = node.oldest_waiting_input(); next >= 0) {
      node.take_message(next);
      refresh_latest_inputs(node);
      lock.unlock();
      node.space.notify_all();
      node.process_taken();
      lock.lock();
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
    node.run_tick();
    lock.lock();
    // A node that runs late skips the ticks it missed instead of bursting to catch up.
    const auto late = std::chrono::steady_clock::now() - start_;
    while (node.tick_time(node.ticks) < late) {
      ++node.ticks;
      ++node.skipped_ticks;
    }
  }
  node.exited = true;
  for (auto& slot : node.inputs)
    if (slot.edge) slot.edge->drop_queued();
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

void RealtimeExecutor::wake_all() {
  for (auto& node : run_.nodes) {
    { std::lock_guard lock(node->mutex); }
    node->wake.notify_all();
    node->space.notify_all();
  }
}

Time RealtimeExecutor::run(Progress& progress) {
  const std::optional<double> duration = run_.duration_s();
  for (const auto& edge : run_.edges)
    if (!edge->config->delayed) ++edge->to->upstream_alive;

  start_ = std::chrono::steady_clock::now();
  std::vector<std::thread> threads;
  threads.reserve(run_.nodes.size());
  for (auto& node : run_.nodes) threads.emplace_back([this, n = node.get()] { node_loop(*n); });

  while (!run_.stopping() && !run_.all_sources_ended()) {
    if (duration && to_seconds(now()) >= *duration) break;
    run_.announce_when_running();
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
