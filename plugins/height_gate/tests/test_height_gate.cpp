// The height gate on a scene whose answer is known: a level camera resting 3 m up sees the test
// scene's detections; those that are lower than 3 m in the world (below the optical axis: camera
// y > 0, y pointing down) are dropped, the others pass unchanged.
#include <gmock/gmock.h>

#include "kestrel/runtime/graph.hpp"
#include "kestrel/runtime/plugin_host.hpp"
#include "kestrel/runtime/run.hpp"
#include "kestrel/testing/plugins.hpp"
#include "test_nodes/scene.hpp"

using namespace kestrel;

TEST(HeightGate, DropsWhatIsLowerThanTheGateAndKeepsTheRest) {
  PluginHost& host = kestrel::testing::built_and_test_plugins();
  const std::string yaml = R"(nodes:
  - {id: hunter, type: quadrotor_sim, params: {ground_z_m: 3.0, initial_position_m: [0.0, 0.0, 3.0]}}
  - {id: scene, type: scene_source, params: {rate_hz: 30, count: 60}}
  - {id: gate, type: height_gate, params: {min_height_m: 3.0}}
connections:
  - {from: hunter.state, to: gate.pose}
  - {from: scene.detections, to: gate.detections}
duration: 2.0
)";
  auto built = build_graph(GraphSource::from_string(yaml, "gate.yaml"), host.registry());
  ASSERT_TRUE(built.graph) << built.diagnostics.str();
  const RunResult r = run_graph(*built.graph, host.registry());
  ASSERT_EQ(r.outcome, RunOutcome::completed) << (r.errors.empty() ? "" : r.errors.front());
  int low = 0;
  for (int k = 0; k < 60; ++k) low += test::scene_position(k).y() > 0.0 ? 1 : 0;
  ASSERT_GT(low, 5);
  ASSERT_LT(low, 55);  // the scene has both
  EXPECT_EQ(r.report.at("gate").at("detections"), 60);
  EXPECT_EQ(r.report.at("gate").at("dropped"), low);
}
