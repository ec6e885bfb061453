// Every class of graph error is found, with its file:line:col, and all are reported at once.
#include <gmock/gmock.h>

#include "kestrel/testing/graphs.hpp"

using namespace kestrel;
using namespace kestrel::testing;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

namespace {

// Two nodes and one connection; tests edit one thing at a time.
const char* kValid = R"(name: valid
nodes:
  - id: src
    type: counter_source
    params: {rate_hz: 10}
  - id: sink
    type: collector
connections:
  - from: src.out
    to: sink.in
)";

std::string only_error(const BuildResult& r) {
  EXPECT_EQ(r.diagnostics.error_count(), 1u) << r.diagnostics.str();
  return r.diagnostics.items().empty() ? "" : r.diagnostics.items().front().str();
}

}  // namespace

TEST(GraphValidation, ValidGraphBuilds) {
  auto r = build(kValid);
  ASSERT_TRUE(r.graph) << r.diagnostics.str();
  EXPECT_EQ(r.graph->nodes.size(), 2u);
  EXPECT_EQ(r.graph->connections.size(), 1u);
  EXPECT_EQ(r.graph->connections[0].label, "src.out -> sink.in");
  EXPECT_EQ(r.graph->nodes[0].params.get<double>("rate_hz"), 10.0);
  EXPECT_EQ(r.graph->nodes[0].params.get<std::int64_t>("count"), 0);  // the declared default
}

TEST(GraphValidation, YamlSyntaxErrorHasLineAndColumn) {
  auto r = build("nodes:\n  - id: a\n    type: [relay\n");
  EXPECT_FALSE(r.graph);
  const std::string e = only_error(r);
  EXPECT_THAT(e, HasSubstr("g.yaml:4:1: error: YAML syntax error"));
}

TEST(GraphValidation, UnknownTopLevelKeySuggestsTheRightOne) {
  std::string yaml = kValid;
  yaml += "executr: lockstep\n";
  EXPECT_THAT(only_error(build(yaml)),
              HasSubstr("g.yaml:11:1: error: unknown key 'executr' in the graph (did you mean 'executor'?)"));
}

TEST(GraphValidation, UnknownNodeTypeListsKnownTypesAndNearest) {
  std::string yaml = kValid;
  yaml.replace(yaml.find("collector"), 9, "colector");
  const std::string e = only_error(build(yaml));
  EXPECT_THAT(e, HasSubstr("g.yaml:7:11: error: unknown node type 'colector' (did you mean 'collector'?)"));
  EXPECT_THAT(e, HasSubstr("known types: adder, blob_relay"));
}

TEST(GraphValidation, UnknownParameterSuggestsTheDeclaredOne) {
  std::string yaml = kValid;
  yaml.replace(yaml.find("rate_hz"), 7, "rate_h");
  EXPECT_THAT(only_error(build(yaml)),
              HasSubstr("g.yaml:5:14: error: node 'src' (counter_source): unknown parameter 'rate_h' (did you mean "
                        "'rate_hz'?)"));
}

TEST(GraphValidation, WrongTypeOutOfRangeAndNotAllowedValues) {
  const char* yaml = R"(nodes:
  - id: src
    type: counter_source
    params: {rate_hz: fast, count: 2.5}
  - id: s
    type: scale
    params: {factor: 1e9, mode: multiplyy, enabled: maybe, offsets: [1, x]}
  - id: sink
    type: collector
connections:
  - {from: src.out, to: s.in}
  - {from: s.out, to: sink.in}
)";
  auto r = build(yaml);
  EXPECT_FALSE(r.graph);
  EXPECT_THAT(messages(r),
              ElementsAre(HasSubstr("g.yaml:4:23: error: node 'src' (counter_source): parameter 'rate_hz' must be a "
                                    "number, not 'fast'"),
                          HasSubstr("g.yaml:4:36: error: node 'src' (counter_source): parameter 'count' must be an "
                                    "integer, not '2.5'"),
                          HasSubstr("g.yaml:7:22: error: node 's' (scale): parameter 'factor' = 1000000000 is out of "
                                    "range [-1000000, 1000000]"),
                          HasSubstr("g.yaml:7:33: error: node 's' (scale): parameter 'mode' = 'multiplyy' is not one "
                                    "of multiply, divide (did you mean 'multiply'?)"),
                          HasSubstr("g.yaml:7:53: error: node 's' (scale): parameter 'enabled' must be true or false"),
                          HasSubstr("g.yaml:7:73: error: node 's' (scale): parameter 'offsets' must hold numbers")));
}

TEST(GraphValidation, UnknownPortSuggestsAndExplainsDirection) {
  std::string yaml = kValid;
  yaml.replace(yaml.find("src.out"), 7, "src.outt");
  EXPECT_THAT(only_error(build(yaml)),
              HasSubstr("g.yaml:9:11: error: node 'src' (counter_source) has no output 'outt' (did you mean 'out'?)"));
  // Written the wrong way round: the message says so, and sink.in is (truly) left unconnected.
  yaml = kValid;
  yaml.replace(yaml.find("sink.in"), 7, "src.out");
  EXPECT_THAT(messages(build(yaml)),
              ElementsAre(HasSubstr("g.yaml:6:5: error: input 'sink.in' (test.Number) is not connected"),
                          HasSubstr("g.yaml:10:9: error: node 'src' (counter_source) has no input 'out'; 'src.out' is "
                                    "an output, and connections go from an output to an input")));
}

TEST(GraphValidation, PortTypeMismatchNamesBothPortsAndTypes) {
  std::string yaml = kValid;
  yaml.replace(yaml.find("counter_source"), 14, "blob_source");
  EXPECT_THAT(
      only_error(build(yaml)),
      HasSubstr("g.yaml:9:5: error: port type mismatch: src.out is test.Blob, but sink.in expects test.Number"));
}

TEST(GraphValidation, UnconnectedInputIsAnErrorUnlessOptional) {
  const char* yaml = R"(nodes:
  - id: src
    type: counter_source
  - id: add
    type: adder
  - id: lonely
    type: collector
connections:
  - {from: src.out, to: add.a}
)";
  EXPECT_THAT(only_error(build(yaml)),
              HasSubstr("g.yaml:6:5: error: input 'lonely.in' (test.Number) is not connected"));
}

TEST(GraphValidation, DuplicateIdPointsAtTheFirstDefinition) {
  std::string yaml = kValid;
  yaml.replace(yaml.find("id: sink"), 8, "id: src");
  const auto r = build(yaml);
  EXPECT_FALSE(r.graph);
  EXPECT_THAT(r.diagnostics.items().front().str(),
              HasSubstr("g.yaml:6:9: error: duplicate node id 'src' (first defined at line 3)"));
}

TEST(GraphValidation, InputTakesOneConnection) {
  std::string yaml = kValid;
  yaml += "  - {from: src.out, to: sink.in}\n";
  EXPECT_THAT(only_error(build(yaml)), HasSubstr("g.yaml:11:25: error: input sink.in is already connected (line 9)"));
}

TEST(GraphValidation, CycleMustBeBrokenByADelayedConnection) {
  const char* yaml = R"(nodes:
  - {id: src, type: counter_source}
  - {id: add, type: adder}
  - {id: twice, type: scale}
  - {id: sink, type: collector}
connections:
  - {from: src.out, to: add.a}
  - {from: add.sum, to: twice.in}
  - {from: twice.out, to: add.b}
  - {from: add.sum, to: sink.in}
)";
  EXPECT_THAT(only_error(build(yaml)),
              HasSubstr("g.yaml:8:5: error: cycle not broken by a delayed connection: add.sum -> twice.in, "
                        "twice.out -> add.b"));
  std::string fixed = yaml;
  fixed.replace(fixed.find("to: add.b}"), 10, "to: add.b, delayed: true}");
  auto r = build(fixed);
  ASSERT_TRUE(r.graph) << r.diagnostics.str();
  // Every non-delayed connection goes forward in the execution order.
  std::vector<int> position(r.graph->nodes.size());
  for (std::size_t i = 0; i < r.graph->topological_order.size(); ++i)
    position[static_cast<std::size_t>(r.graph->topological_order[i])] = static_cast<int>(i);
  for (const auto& c : r.graph->connections) {
    if (!c.delayed) {
      EXPECT_LT(position[static_cast<std::size_t>(c.from_node)], position[static_cast<std::size_t>(c.to_node)]);
    }
  }
}

TEST(GraphValidation, OverridesAreValidatedLikeFileValues) {
  auto ok = build(kValid, {"src.rate_hz=20"});
  ASSERT_TRUE(ok.graph) << ok.diagnostics.str();
  EXPECT_EQ(ok.graph->nodes[0].params.get<double>("rate_hz"), 20.0);

  EXPECT_THAT(only_error(build(kValid, {"src.rate=20"})),
              HasSubstr("--set src.rate=20: error: node 'src' (counter_source): unknown parameter 'rate' (did you mean "
                        "'rate_hz'?)"));
  EXPECT_THAT(only_error(build(kValid, {"src.rate_hz=-1"})), HasSubstr("out of range"));
  EXPECT_THAT(only_error(build(kValid, {"snk.keep=1"})),
              HasSubstr("no node 'snk' in the graph (did you mean 'sink'?)"));
  EXPECT_THAT(only_error(build(kValid, {"rate_hz=1"})), HasSubstr("expected --set node.param=value"));
}

TEST(GraphValidation, ExecutorClockAndPolicyErrors) {
  std::string yaml = kValid;
  yaml += "executor: {type: realtime, default_policy: fifo zero}\nclock: simulated\non_error: ignore\n";
  yaml.replace(yaml.find("    to: sink.in"), 15, "    to: sink.in\n    policy: lifo");
  auto r = build(yaml);
  EXPECT_THAT(messages(r), ElementsAre(HasSubstr("g.yaml:11:13: error: bad queue policy 'lifo'"),
                                       HasSubstr("g.yaml:12:44: error: bad queue policy 'fifo zero'"),
                                       HasSubstr("g.yaml:13:8: error: the realtime executor runs on the wall clock"),
                                       HasSubstr("g.yaml:14:11: error: unknown on_error policy 'ignore'")));
}

// What a node needs of the executor is in its spec: a graph that runs it under the other one is
// refused at the node's type, with the reason; the executor the command line chooses counts.
TEST(GraphValidation, ANodeUnderTheExecutorItCannotRunWithIsRefusedAtItsType) {
  const std::string yaml = R"(nodes:
  - {id: src, type: counter_source, params: {rate_hz: 10, count: 3}}
  - {id: device, type: realtime_only}
  - {id: check, type: lockstep_only}
connections:
  - {from: src.out, to: device.in}
)";
  EXPECT_THAT(messages(build(yaml)),
              ElementsAre(HasSubstr("g.yaml:3:24: error: node 'device' (realtime_only) needs the realtime executor: it "
                                    "stands for a real device, but the graph runs lockstep (the graph's 'executor'); "
                                    "set 'executor: realtime' in the graph or run it with --executor realtime")));
  const auto as_realtime = build_graph(GraphSource::from_string(yaml, "g.yaml"),
                                       kestrel::testing::test_plugins().registry(), {}, {}, ExecutorKind::realtime);
  EXPECT_THAT(messages(as_realtime),
              ElementsAre(HasSubstr("g.yaml:4:23: error: node 'check' (lockstep_only) needs the lockstep executor: it "
                                    "checks a step-by-step result, but the graph runs realtime (--executor)")));
  const auto header_realtime = build(yaml + "executor: realtime\n");
  EXPECT_THAT(messages(header_realtime), ElementsAre(HasSubstr("g.yaml:4:23: error: node 'check' (lockstep_only)")));
}

TEST(GraphValidation, EveryProblemIsReportedInOnePass) {
  const char* yaml = R"(nodes:
  - {id: src, type: counter_source, params: {rate_hz: 0}}
  - {id: x, type: nonsense}
  - {id: sink, type: collector, params: {kep: 3}}
connections:
  - {from: src.out, to: sink.inn}
)";
  auto r = build(yaml);
  EXPECT_FALSE(r.graph);
  EXPECT_THAT(
      messages(r),
      ElementsAre(
          HasSubstr("g.yaml:2:55: error: node 'src' (counter_source): parameter 'rate_hz' = 0 is out of range [0.001, "
                    "1000000] Hz"),
          HasSubstr("g.yaml:3:19: error: unknown node type 'nonsense'"),
          HasSubstr("g.yaml:4:42: error: node 'sink' (collector): unknown parameter 'kep' (did you mean 'keep'?)"),
          HasSubstr("g.yaml:6:25: error: node 'sink' (collector) has no input 'inn' (did you mean 'in'?)")));
}

TEST(QueuePolicy, ParsesEveryForm) {
  EXPECT_EQ(QueuePolicy::parse("latest")->str(), "latest");
  EXPECT_EQ(QueuePolicy::parse("fifo")->str(), "fifo 16");
  EXPECT_EQ(QueuePolicy::parse("fifo 3")->str(), "fifo 3");
  EXPECT_EQ(QueuePolicy::parse("block")->str(), "block 1");
  EXPECT_EQ(QueuePolicy::parse("block 8")->str(), "block 8");
  EXPECT_FALSE(QueuePolicy::parse("fifo 0"));
  EXPECT_FALSE(QueuePolicy::parse("fifo 3 4"));
  EXPECT_FALSE(QueuePolicy::parse("lifo"));
}

TEST(GraphValidation, MalformedStructuresGiveErrorsNotCrashes) {
  const std::vector<std::string> documents = {
      "",
      "42",
      "[1, 2]",
      "nodes: 5",
      "nodes: [1, [2], {}]",
      "nodes: [{id: [a], type: {x: 1}}]",
      "nodes: [{id: a, type: relay, params: [1, 2]}]",
      "nodes: [{id: a, type: scale, params: {factor: [1], mode: {a: b}, offsets: 3}}]",
      "nodes: [{id: 'a.b', type: relay}]",
      "nodes: []\nconnections: {a: b}",
      "nodes: []\nconnections: [5, {from: 1}, {from: a, to: b}, {from: a.b.c, to: .x}]",
      "executor: [1]\nclock: {}\nseed: -3\nduration: -1\nnodes: []",
      "executor: {type: {a: 1}}\nclock: {type: wall, real_time_factor: zero}\nnodes: []",
      "kestrel: 2\nplugin_paths: nope\nnodes: []",
      "nodes: [{id: a, type: relay, params: {a: 1, a: 2}}]",
      "nodes:\n  - id: x\n    type: counter_source\n    params: {rate_hz: .nan}",
  };
  for (const auto& doc : documents) {
    const auto r = build(doc);
    EXPECT_FALSE(r.graph) << doc;
    EXPECT_TRUE(r.diagnostics.has_errors()) << doc;
    for (const auto& d : r.diagnostics.items()) EXPECT_EQ(d.where.file, "g.yaml") << doc;
  }
}

TEST(GraphValidation, ABrokenRuleIsReportedWhereAParameterItNamesIsSet) {
  const char* yaml = R"(nodes:
  - id: src
    type: counter_source
  - id: w
    type: window
    params:
      low: 5
      high: 2
  - id: sink
    type: collector
connections:
  - {from: src.out, to: w.in}
  - {from: w.out, to: sink.in}
)";
  EXPECT_THAT(only_error(build(yaml)),
              HasSubstr("g.yaml:7:12: error: node 'w' (window): low = 5, high = 2 break the rule 'low <= high'"));
  // Each value is valid on its own; only the pair is wrong. A --set that mends it makes a valid graph,
  // and one that breaks it is reported at the --set.
  EXPECT_TRUE(build(yaml, {"w.low=1"}).graph);
  std::string fine = yaml;
  fine.replace(fine.find("high: 2"), 7, "high: 9");
  EXPECT_TRUE(build(fine).graph);
  EXPECT_THAT(only_error(build(fine, {"w.high=0"})), HasSubstr("--set w.high=0: error: node 'w' (window): low = 5, "
                                                               "high = 0 break the rule 'low <= high'"));
}

TEST(GraphValidation, AComponentsRulesAreCheckedInPlace) {
  const char* yaml = R"(nodes:
  - id: src
    type: counter_source
  - id: s
    type: shape
    params:
      shaper: {type: clamp, low: 3, high: 1}
  - id: sink
    type: collector
connections:
  - {from: src.out, to: s.in}
  - {from: s.out, to: sink.in}
)";
  EXPECT_THAT(only_error(build(yaml)),
              HasSubstr("g.yaml:7:34: error: node 's' (shape) shaper 'clamp': low = 3, high = 1 break the rule "
                        "'low <= high'"));
}

TEST(GraphValidation, OverridesReachIntoComponents) {
  const char* yaml = R"(nodes:
  - id: src
    type: counter_source
  - id: s
    type: shape
  - id: sink
    type: collector
connections:
  - {from: src.out, to: s.in}
  - {from: s.out, to: sink.in}
)";
  // The default component (offset) with one of its parameters set from outside.
  auto r = build(yaml, {"s.shaper.amount=5"});
  ASSERT_TRUE(r.graph) << r.diagnostics.str();
  const auto shaper = r.graph->nodes[1].params.get<ComponentConfig>("shaper");
  EXPECT_EQ(shaper.type, "offset");
  EXPECT_EQ(shaper.params->get<double>("amount"), 5.0);
  // Another component, then its parameters; checked like the graph's own values.
  r = build(yaml, {"s.shaper=clamp", "s.shaper.high=4"});
  ASSERT_TRUE(r.graph) << r.diagnostics.str();
  EXPECT_EQ(r.graph->nodes[1].params.get<ComponentConfig>("shaper").params->get<double>("high"), 4.0);
  EXPECT_THAT(only_error(build(yaml, {"s.shaper=clamp", "s.shaper.high=-4"})),
              HasSubstr("--set s.shaper.high=-4: error: node 's' (shape) shaper 'clamp': low = 0, high = -4 break the "
                        "rule 'low <= high'"));
  EXPECT_THAT(
      only_error(build(yaml, {"s.shaper.amont=5"})),
      HasSubstr("--set s.shaper.amont=5: error: node 's' (shape) shaper 'offset': unknown parameter 'amont' (did "
                "you mean 'amount'?)"));
  EXPECT_THAT(only_error(build(yaml, {"src.rate_hz.x=1"})),
              HasSubstr("node 'src' (counter_source): parameter 'rate_hz' is not a component, so 'rate_hz.x' names "
                        "nothing"));
}
