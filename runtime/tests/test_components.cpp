// Components: built by name from a node's parameter, with their own validated parameters.
#include <gmock/gmock.h>

#include "kestrel/testing/graphs.hpp"

using namespace kestrel;
using namespace kestrel::testing;
using ::testing::HasSubstr;

namespace {

std::string shaper_graph(const std::string& shaper) {
  return R"(nodes:
  - {id: src, type: counter_source, params: {rate_hz: 10, count: 4}}
  - id: s
    type: shape
    params:
      shaper: )" +
         shaper + R"(
  - {id: sink, type: collector}
connections:
  - {from: src.out, to: s.in}
  - {from: s.out, to: sink.in}
)";
}

std::vector<double> values(const RunResult& r) { return r.report.at("sink").at("values").get<std::vector<double>>(); }

}  // namespace

TEST(Components, RegisteredByKindAndName) {
  const auto& registry = test_plugins().registry();
  EXPECT_THAT(registry.component_names("shaper"), ::testing::UnorderedElementsAre("offset", "clamp"));
  ASSERT_NE(registry.find_component("shaper", "clamp"), nullptr);
  EXPECT_EQ(registry.find_component("shaper", "clamp")->spec.params().size(), 2u);
}

TEST(Components, ByNameWithDefaultsOrAsAMapWithParameters) {
  EXPECT_THAT(values(run(shaper_graph("offset"))), ::testing::ElementsAre(1, 2, 3, 4));
  EXPECT_THAT(values(run(shaper_graph("{type: offset, amount: 10}"))), ::testing::ElementsAre(10, 11, 12, 13));
  EXPECT_THAT(values(run(shaper_graph("{type: clamp, low: 1, high: 2}"))), ::testing::ElementsAre(1, 1, 2, 2));
  // The node's declared default applies when the parameter is absent.
  auto r = build(shaper_graph("offset"));
  ASSERT_TRUE(r.graph);
  EXPECT_EQ(r.graph->nodes[1].params.get<ComponentConfig>("shaper").type, "offset");
}

TEST(Components, UnknownComponentsAndTheirParametersAreLocated) {
  EXPECT_THAT(messages(build(shaper_graph("clmp"))),
              ::testing::ElementsAre(HasSubstr(
                  "g.yaml:6:15: error: node 's' (shape): unknown shaper 'clmp' (did you mean 'clamp'?); known: ")));
  EXPECT_THAT(messages(build(shaper_graph("{type: clamp, hgh: 3}"))),
              ::testing::ElementsAre(HasSubstr("g.yaml:6:29: error: node 's' (shape) shaper 'clamp': unknown parameter "
                                               "'hgh' (did you mean 'high'?)")));
  EXPECT_THAT(
      messages(build(shaper_graph("{type: offset, amount: 1000}"))),
      ::testing::ElementsAre(HasSubstr("g.yaml:6:38: error: node 's' (shape) shaper 'offset': parameter 'amount' = "
                                       "1000 is out of range [-100, 100]")));
  EXPECT_THAT(messages(build(shaper_graph("{amount: 3}"))),
              ::testing::ElementsAre(HasSubstr("needs a 'type' naming the shaper")));
  // Overrides replace the whole component.
  auto r = build(shaper_graph("offset"), {"s.shaper={type: clamp, high: 0.5}"});
  ASSERT_TRUE(r.graph) << r.diagnostics.str();
  EXPECT_EQ(r.graph->nodes[1].params.get<ComponentConfig>("shaper").type, "clamp");
}
