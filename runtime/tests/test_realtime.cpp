// The realtime executor: a thread per node, bounded queues with counted drops, clean shutdown.
#include <gmock/gmock.h>

#include <thread>

#include "kestrel/testing/graphs.hpp"

using namespace kestrel;
using namespace kestrel::testing;

namespace {

// A fast source feeding a slow node through a connection with the given policy.
std::string overload_graph(const std::string& policy) {
  return R"(executor: realtime
nodes:
  - {id: src, type: counter_source, params: {rate_hz: 500}}
  - {id: slow, type: slow, params: {delay_ms: 10}}
  - {id: sink, type: collector}
connections:
  - {from: src.out, to: slow.in, policy: ")" +
         policy + R"("}
  - {from: slow.out, to: sink.in, policy: fifo 1000}
duration: 0.6
)";
}

std::uint64_t received(const RunResult& r) { return r.report.at("sink").at("count").get<std::uint64_t>(); }

}  // namespace

TEST(Realtime, FifoDropsTheOldestAndCountsEveryDrop) {
  const auto r = run(overload_graph("fifo 4"));
  const auto& edge = connection_stats(r, "src.out -> slow.in");
  EXPECT_GT(edge.drops, 100u);
  EXPECT_LE(edge.high_water, 4u);
  // Nothing vanishes: every message was either processed or counted as dropped.
  EXPECT_EQ(node_stats(r, "src").messages_out, edge.delivered);
  EXPECT_EQ(edge.delivered - edge.drops, received(r));
  EXPECT_EQ(node_stats(r, "slow").drops, edge.drops);
  // fifo keeps the oldest waiting messages in order, so the sink sees increasing indices.
  const auto idx = r.report.at("sink").at("indices").get<std::vector<std::int64_t>>();
  EXPECT_TRUE(std::is_sorted(idx.begin(), idx.end()));
}

TEST(Realtime, LatestKeepsOnlyTheNewest) {
  const auto r = run(overload_graph("latest"));
  const auto& edge = connection_stats(r, "src.out -> slow.in");
  EXPECT_GT(edge.drops, 100u);
  EXPECT_EQ(edge.high_water, 1u);
  EXPECT_EQ(edge.delivered - edge.drops, received(r));
}

TEST(Realtime, BlockAppliesBackpressureAndDropsNothing) {
  const auto r = run(overload_graph("block 2"));
  const auto& edge = connection_stats(r, "src.out -> slow.in");
  EXPECT_EQ(edge.drops, 0u);
  EXPECT_LE(edge.high_water, 2u);
  // The source was held back to the slow node's pace (about 100/s, not 500/s).
  EXPECT_LT(node_stats(r, "src").messages_out, 150u);
  EXPECT_EQ(edge.delivered, received(r));
}

TEST(Realtime, LatestInputDoesNotTriggerAndTriggeringInputDoes) {
  const auto r = run(R"(executor: realtime
nodes:
  - {id: a, type: counter_source, params: {rate_hz: 50}}
  - {id: b, type: counter_source, params: {rate_hz: 200}}
  - {id: add, type: adder}
  - {id: sink, type: collector}
connections:
  - {from: a.out, to: add.a}
  - {from: b.out, to: add.b}
  - {from: add.sum, to: sink.in}
duration: 0.5
)");
  // One sum per message on `a`, none for the four times as many on `b`.
  EXPECT_EQ(node_stats(r, "add").messages_out, node_stats(r, "a").messages_out);
  EXPECT_EQ(node_stats(r, "add").calls, node_stats(r, "a").messages_out);
  EXPECT_GT(node_stats(r, "add").messages_in, 3 * node_stats(r, "a").messages_out);
}

TEST(Realtime, StopDrainsQueuesAndFlushesSinks) {
  std::atomic<bool> stop{false};
  RunOptions options;
  options.stop_flag = &stop;
  std::thread stopper([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    stop = true;
  });
  const auto r = run(R"(executor: realtime
nodes:
  - {id: src, type: counter_source, params: {rate_hz: 200}}
  - {id: slow, type: slow, params: {delay_ms: 2}}
  - {id: sink, type: collector}
connections:
  - {from: src.out, to: slow.in, policy: fifo 1000}
  - {from: slow.out, to: sink.in, policy: fifo 1000}
)",
                     options);
  stopper.join();
  EXPECT_EQ(r.outcome, RunOutcome::stopped);
  EXPECT_EQ(r.exit_code(), 0);
  // Every published message reached the sink: the queues drained before the sink's finish().
  EXPECT_GT(node_stats(r, "src").messages_out, 20u);
  EXPECT_EQ(received(r), node_stats(r, "src").messages_out);
  for (const auto& c : r.connections) EXPECT_EQ(c.drops, 0u) << c.label;
}

TEST(Realtime, EndsWhenEverySourceHasEnded) {
  const auto r = run(R"(executor: realtime
nodes:
  - {id: src, type: counter_source, params: {rate_hz: 1000, count: 50}}
  - {id: sink, type: collector}
connections:
  - {from: src.out, to: sink.in, policy: fifo 100}
)");
  EXPECT_EQ(r.outcome, RunOutcome::completed);
  EXPECT_EQ(received(r), 50u);
}

// sum_k = k + (latest b) with b = sum_j / 2 for the newest sum_j that has come back round the
// loop, or 0 before the first one. On the wall clock which j that is depends on thread timing,
// so each value is checked against the sums published before it: it must be k plus half of one
// of them, the feedback must never go back in time, and it must have arrived at all.
TEST(Realtime, DelayedFeedbackLoopComputesFromEarlierSums) {
  const auto r = run(R"(executor: realtime
nodes:
  - {id: src, type: counter_source, params: {rate_hz: 100}}
  - {id: add, type: adder}
  - {id: half, type: scale, params: {factor: 0.5}}
  - {id: sink, type: collector}
connections:
  - {from: src.out, to: add.a, policy: fifo 1000}
  - {from: add.sum, to: half.in, policy: fifo 1000}
  - {from: half.out, to: add.b, delayed: true}
  - {from: add.sum, to: sink.in, policy: fifo 1000}
duration: 0.3
)");
  EXPECT_EQ(r.outcome, RunOutcome::completed);
  const auto sums = r.report.at("sink").at("values").get<std::vector<double>>();
  const auto indices = r.report.at("sink").at("indices").get<std::vector<std::int64_t>>();
  ASSERT_GT(sums.size(), 10u);
  // Every sum reached the sink, in order: one per source message.
  EXPECT_EQ(sums.size(), node_stats(r, "src").messages_out);
  ASSERT_EQ(indices.size(), sums.size());
  for (std::size_t k = 0; k < indices.size(); ++k) ASSERT_EQ(indices[k], static_cast<std::int64_t>(k));

  int previous = -1;  // index of the sum fed back last time; -1: none yet
  std::size_t fed_back = 0;
  for (std::size_t k = 0; k < sums.size(); ++k) {
    const double b = sums[k] - static_cast<double>(k);
    if (b == 0.0 && previous < 0) continue;  // nothing has come back yet (sums are >= k, so b > 0 after)
    int j = -1;
    for (std::size_t i = 0; i < k; ++i)
      if (std::abs(b - 0.5 * sums[i]) <= 1e-9 * std::max(1.0, sums[i])) j = static_cast<int>(i);
    ASSERT_GE(j, 0) << "sum " << k << " = " << sums[k] << " is not " << k << " + half of an earlier sum";
    EXPECT_GE(j, previous) << "the feedback of sum " << k << " went back in time";
    previous = j;
    ++fed_back;
  }
  EXPECT_GT(fed_back, 0u) << "nothing came back round the loop";
  // The loop takes microseconds and the source ticks every 10 ms: the feedback keeps up, so the
  // last sums are built on recent ones, not on a value that stopped changing.
  EXPECT_GE(previous, static_cast<int>(sums.size() / 2)) << "the feedback stopped following the sums";
  EXPECT_DOUBLE_EQ(sums[0], 0.0);  // nothing to add before the first sum
}
