// A node that throws is named in the error; on_error decides between stopping and skipping.
#include <gmock/gmock.h>

#include "kestrel/testing/graphs.hpp"

using namespace kestrel;
using namespace kestrel::testing;
using ::testing::HasSubstr;

namespace {

std::string faulty_graph(const std::string& executor, const std::string& on_error) {
  return "executor: " + executor + "\non_error: " + on_error + R"(
nodes:
  - {id: src, type: counter_source, params: {rate_hz: 100, count: 30}}
  - {id: picky, type: faulty, params: {fail_every: 3}}
  - {id: sink, type: collector}
connections:
  - {from: src.out, to: picky.in, policy: fifo 100}
  - {from: picky.out, to: sink.in, policy: fifo 100}
)";
}

}  // namespace

class OnError : public ::testing::TestWithParam<std::string> {};

TEST_P(OnError, SkipDropsTheFailedMessageAndGoesOn) {
  const auto r = run(faulty_graph(GetParam(), "skip"));
  EXPECT_EQ(r.outcome, RunOutcome::completed);
  EXPECT_EQ(r.exit_code(), 0);
  EXPECT_EQ(node_stats(r, "picky").errors, 10u);
  EXPECT_EQ(r.report.at("sink").at("count"), 20);
  ASSERT_EQ(r.errors.size(), 10u);
  EXPECT_EQ(r.errors.front(), "node 'picky' (faulty): bad number 2");
}

TEST_P(OnError, StopEndsTheRunWithAFailure) {
  const auto r = run(faulty_graph(GetParam(), "stop"));
  EXPECT_EQ(r.outcome, RunOutcome::failed);
  EXPECT_EQ(r.exit_code(), 1);
  ASSERT_FALSE(r.errors.empty());
  EXPECT_EQ(r.errors.front(), "node 'picky' (faulty): bad number 2");
  EXPECT_LT(r.report.at("sink").at("count").get<int>(), 20);
  EXPECT_EQ(r.report.at("outcome"), "failed");
}

TEST_P(OnError, ANodeThatCannotStartFailsTheRunBeforeItBegins) {
  auto yaml = faulty_graph(GetParam(), "skip");
  yaml.replace(yaml.find("fail_every: 3"), 13, "fail_on_start: true");
  const auto r = run(yaml);
  EXPECT_EQ(r.outcome, RunOutcome::failed);
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_EQ(r.errors.front(), "node 'picky' (faulty): could not start: cannot open the imaginary device");
  EXPECT_EQ(node_stats(r, "src").messages_out, 0u);
}

// Named after the executor: the realtime instances carry the CTest label `threads`.
INSTANTIATE_TEST_SUITE_P(Executors, OnError, ::testing::Values("lockstep", "realtime"),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });
