// The lockstep executor: simulated time, fixed order, every message processed, reproducible.
#include <gmock/gmock.h>

#include "kestrel/testing/graphs.hpp"

using namespace kestrel;
using namespace kestrel::testing;

namespace {

std::vector<double> values(const RunResult& r, const std::string& sink) {
  return r.report.at(sink).at("values").get<std::vector<double>>();
}

}  // namespace

TEST(Lockstep, SourceTicksAtItsRateOnTheSimulatedClock) {
  auto r = run(R"(nodes:
  - {id: src, type: counter_source, params: {rate_hz: 10}}
  - {id: sink, type: collector}
connections:
  - {from: src.out, to: sink.in}
duration: 1.0
)");
  EXPECT_EQ(r.outcome, RunOutcome::completed);
  EXPECT_THAT(values(r, "sink"), ::testing::ElementsAre(0, 1, 2, 3, 4, 5, 6, 7, 8, 9));
  const auto times = r.report.at("sink").at("times_s").get<std::vector<double>>();
  ASSERT_EQ(times.size(), 10u);
  for (std::size_t i = 0; i < times.size(); ++i) EXPECT_DOUBLE_EQ(times[i], 0.1 * static_cast<double>(i));
  EXPECT_EQ(node_stats(r, "src").messages_out, 10u);
  EXPECT_EQ(node_stats(r, "sink").messages_in, 10u);
  EXPECT_EQ(connection_stats(r, "src.out -> sink.in").drops, 0u);
}

TEST(Lockstep, RunEndsWhenEverySourceHasEnded) {
  auto r = run(R"(nodes:
  - {id: src, type: counter_source, params: {rate_hz: 100, count: 5}}
  - {id: sink, type: collector}
connections:
  - {from: src.out, to: sink.in}
)");
  EXPECT_EQ(r.outcome, RunOutcome::completed);
  EXPECT_THAT(values(r, "sink"), ::testing::ElementsAre(0, 1, 2, 3, 4));
  EXPECT_NEAR(r.sim_time_s, 0.04, 1e-12);
}

TEST(Lockstep, NeverDropsEvenWithATinyQueuePolicy) {
  // Policies shape realtime queues; lockstep processes every message whatever they say.
  auto r = run(R"(nodes:
  - {id: src, type: counter_source, params: {rate_hz: 1000}}
  - {id: slow, type: slow, params: {delay_ms: 0}}
  - {id: sink, type: collector}
connections:
  - {from: src.out, to: slow.in, policy: latest}
  - {from: slow.out, to: sink.in, policy: fifo 1}
duration: 0.5
)");
  EXPECT_EQ(r.report.at("sink").at("count"), 500);
  for (const auto& c : r.connections) EXPECT_EQ(c.drops, 0u) << c.label;
}

TEST(Lockstep, DelayedFeedbackArrivesAtTheNextStep) {
  // sum_k = k + 2 * sum_(k-1): the doubled sum comes back one tick later.
  auto r = run(R"(nodes:
  - {id: src, type: counter_source, params: {rate_hz: 10, count: 5}}
  - {id: add, type: adder}
  - {id: twice, type: scale, params: {factor: 2}}
  - {id: sink, type: collector}
connections:
  - {from: src.out, to: add.a}
  - {from: add.sum, to: twice.in}
  - {from: twice.out, to: add.b, delayed: true}
  - {from: add.sum, to: sink.in}
)");
  EXPECT_THAT(values(r, "sink"), ::testing::ElementsAre(0, 1, 4, 11, 26));
}

TEST(Lockstep, FanOutSharesOneMessageAndFanInKeepsPublicationOrder) {
  auto r = run(R"(nodes:
  - {id: src, type: counter_source, params: {rate_hz: 10, count: 3}}
  - {id: a, type: relay}
  - {id: b, type: scale, params: {factor: 10}}
  - {id: sink_a, type: collector}
  - {id: sink_b, type: collector}
connections:
  - {from: src.out, to: a.in}
  - {from: src.out, to: b.in}
  - {from: a.out, to: sink_a.in}
  - {from: b.out, to: sink_b.in}
)");
  EXPECT_THAT(values(r, "sink_a"), ::testing::ElementsAre(0, 1, 2));
  EXPECT_THAT(values(r, "sink_b"), ::testing::ElementsAre(0, 10, 20));
}

TEST(Lockstep, SameSeedGivesBitIdenticalOutputsAndAnotherSeedDoesNot) {
  const char* yaml = R"(nodes:
  - {id: src, type: counter_source, params: {rate_hz: 30, noise: 0.5}}
  - {id: other, type: counter_source, params: {rate_hz: 7, noise: 2.0}}
  - {id: add, type: adder}
  - {id: sink, type: collector}
connections:
  - {from: src.out, to: add.a}
  - {from: other.out, to: add.b}
  - {from: add.sum, to: sink.in}
duration: 20
seed: 7
)";
  const auto first = run(yaml);
  const auto second = run(yaml);
  RunOptions other_seed;
  other_seed.seed = 8;
  const auto third = run(yaml, other_seed);
  ASSERT_EQ(first.report.at("sink").at("count"), 600);
  EXPECT_EQ(first.report.at("sink"), second.report.at("sink"));
  EXPECT_NE(first.report.at("sink").at("checksum"), third.report.at("sink").at("checksum"));
}

TEST(Lockstep, ExternalStopFlagEndsTheRunCleanly) {
  std::atomic<bool> stop{true};
  RunOptions options;
  options.stop_flag = &stop;
  auto r = run(R"(nodes:
  - {id: src, type: counter_source}
  - {id: sink, type: collector}
connections:
  - {from: src.out, to: sink.in}
)",
               options);
  EXPECT_EQ(r.outcome, RunOutcome::stopped);
  EXPECT_EQ(r.exit_code(), 0);
  EXPECT_TRUE(r.report.contains("sink"));  // finish() ran
}
