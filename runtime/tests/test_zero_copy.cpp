// The zero-copy promise (docs/architecture.md): a published message is one immutable object that
// every subscriber receives as it is. Counted messages count their copies; every node records
// the address of each message it sees. One publisher fans out to two sinks, a relay and a node
// with several inputs (two triggering, one latest), whose output feeds one more sink.
#include <gmock/gmock.h>

#include <map>

#include "kestrel/testing/graphs.hpp"

using namespace kestrel;
using namespace kestrel::testing;

namespace {

constexpr int kCount = 40;

std::string fan_graph(const std::string& executor) {
  return "executor: " + executor + R"(
nodes:
  - {id: src, type: counted_source, params: {rate_hz: 200, count: 40}}
  - {id: sink_a, type: counted_sink}
  - {id: sink_b, type: counted_sink}
  - {id: relay, type: counted_relay}
  - {id: join, type: counted_join}
  - {id: after_join, type: counted_sink}
connections:
  - {from: src.out, to: sink_a.in, policy: fifo 1000}
  - {from: src.out, to: sink_b.in, policy: fifo 1000}
  - {from: src.out, to: join.a, policy: fifo 1000}
  - {from: src.out, to: relay.in, policy: fifo 1000}
  - {from: relay.out, to: join.b, policy: fifo 1000}
  - {from: src.out, to: join.c}
  - {from: join.out, to: after_join.in, policy: fifo 1000}
)";
}

struct Seen {
  std::vector<std::int64_t> indices;
  std::vector<std::uint64_t> addresses;
};

Seen seen(const nlohmann::json& j) {
  return {j.at("indices").get<std::vector<std::int64_t>>(), j.at("addresses").get<std::vector<std::uint64_t>>()};
}

// Every message seen is the very object the source published with that index.
void expect_originals(const Seen& s, const std::vector<std::uint64_t>& published, const std::string& where) {
  ASSERT_EQ(s.indices.size(), s.addresses.size()) << where;
  for (std::size_t i = 0; i < s.indices.size(); ++i) {
    const auto k = static_cast<std::size_t>(s.indices[i]);
    ASSERT_LT(k, published.size()) << where;
    EXPECT_EQ(s.addresses[i], published[k]) << where << ": message " << k << " is not the published object";
  }
}

std::vector<std::int64_t> all_indices() {
  std::vector<std::int64_t> v(kCount);
  for (int k = 0; k < kCount; ++k) v[static_cast<std::size_t>(k)] = k;
  return v;
}

}  // namespace

class ZeroCopy : public ::testing::TestWithParam<std::string> {};

TEST_P(ZeroCopy, EverySubscriberGetsThePublishedObjectAndNothingIsCopied) {
  const auto r = run(fan_graph(GetParam()));
  ASSERT_EQ(r.outcome, RunOutcome::completed);
  for (const auto& c : r.connections) EXPECT_EQ(c.drops, 0u) << c.label;

  const auto published = r.report.at("src").at("addresses").get<std::vector<std::uint64_t>>();
  ASSERT_EQ(published.size(), static_cast<std::size_t>(kCount));
  EXPECT_EQ(r.report.at("src").at("copies"), 0) << "messages were copied on their way";

  // Fan-out: both sinks saw every message, in order, as the published object.
  for (const char* sink : {"sink_a", "sink_b"}) {
    const Seen s = seen(r.report.at(sink));
    EXPECT_EQ(s.indices, all_indices()) << sink;
    expect_originals(s, published, sink);
  }
  // Fan-in: the node with several inputs saw each message on both triggering inputs (once
  // straight, once through the relay) and on its latest input, always the published object.
  const auto& join = r.report.at("join");
  for (const char* input : {"a", "b"}) {
    const Seen s = seen(join.at(input));
    EXPECT_EQ(s.indices, all_indices()) << "join." << input;
    expect_originals(s, published, std::string("join.") + input);
  }
  const Seen latest = seen(join.at("c"));
  // Read at each of its calls; under realtime the first calls may come before its first value.
  if (GetParam() == "lockstep") {
    EXPECT_EQ(latest.indices.size(), static_cast<std::size_t>(2 * kCount));
  }
  EXPECT_GT(latest.indices.size(), 0u);
  expect_originals(latest, published, "join.c");
  // ... and what it republished reached the next sink uncopied too.
  const Seen after = seen(r.report.at("after_join"));
  EXPECT_EQ(after.indices.size(), static_cast<std::size_t>(2 * kCount));
  expect_originals(after, published, "after_join");
}

// Named after the executor: the realtime instance carries the CTest label `threads`.
INSTANTIATE_TEST_SUITE_P(Executors, ZeroCopy, ::testing::Values("lockstep", "realtime"),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });
