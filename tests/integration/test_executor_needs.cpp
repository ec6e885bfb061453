// A node whose need of an executor depends on its parameters is refused under the other executor
// when the graph is built, at its type, with the reason: dds_bridge needs the realtime executor
// only when it subscribes to DDS topics.
#include <gmock/gmock.h>

#include "kestrel/runtime/graph.hpp"
#include "kestrel/testing/plugins.hpp"

using namespace kestrel;

namespace {

BuildResult bridge_graph(const std::string& executor, const std::string& params) {
  const std::string yaml =
      "executor: " + executor + "\nnodes:\n  - id: bridge\n    type: dds_bridge\n    params: {" + params + "}\n";
  return build_graph(GraphSource::from_string(yaml, "bridge.yaml"), kestrel::testing::built_plugins().registry());
}

}  // namespace

TEST(ExecutorNeeds, ADdsBridgeThatSubscribesNeedsTheRealtimeExecutor) {
  const auto subscribing = bridge_graph("lockstep", "truth_topic: /camera/truth");
  EXPECT_FALSE(subscribing.graph);
  EXPECT_THAT(
      subscribing.diagnostics.str(),
      ::testing::HasSubstr("bridge.yaml:4:11: error: node 'bridge' (dds_bridge) needs the realtime executor: it "
                           "subscribes to DDS topics (what arrives is not in lockstep), but the graph runs "
                           "lockstep"));
  // Publishing only, it runs under either.
  const auto publishing = bridge_graph("lockstep", "");
  EXPECT_TRUE(publishing.graph) << publishing.diagnostics.str();
  const auto realtime = bridge_graph("realtime", "truth_topic: /camera/truth");
  EXPECT_TRUE(realtime.graph) << realtime.diagnostics.str();
}
