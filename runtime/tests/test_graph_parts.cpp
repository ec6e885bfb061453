// Parts: graph files included under a namespace of their own, reached only through the ports they
// declare and configured through their args; one part included twice; every misuse reported at
// its file:line:col.
#include <gmock/gmock.h>

#include <filesystem>
#include <fstream>

#include "kestrel/testing/graphs.hpp"
#include "kestrel/testing/scratch_path.hpp"

using namespace kestrel;
using namespace kestrel::testing;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

namespace {

class PartFiles {
 public:
  explicit PartFiles(const std::string& name) : dir_(kestrel::testing::scratch_path("kestrel-parts-" + name)) {
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "parts");
  }
  ~PartFiles() { fs::remove_all(dir_); }
  void write(const std::string& name, const std::string& text) const { std::ofstream(dir_ / name) << text; }
  BuildResult build(const std::string& name, const std::vector<std::string>& overrides = {}) const {
    return build_graph(GraphSource::from_file(dir_ / name), test_plugins().registry(), overrides);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

 private:
  fs::path dir_;
};

// Numbers in, each multiplied by `factor`, then relayed out.
const char* kScaler = R"(part: scaler
description: multiplies each number by a factor
inputs:
  numbers: {to: scale.in, type: test.Number, description: the numbers to scale}
outputs:
  scaled: {from: relay.out}
args:
  factor: {default: 2.0, description: what each number is multiplied by, to: scale.factor}
nodes:
  - id: scale
    type: scale
  - id: relay
    type: relay
connections:
  - {from: scale.out, to: relay.in}
)";

std::vector<double> received(const RunResult& r, const std::string& sink) {
  return r.report.at(sink).at("values").get<std::vector<double>>();
}

const NodeConfig* node_named(const GraphConfig& g, const std::string& id) {
  for (const auto& n : g.nodes)
    if (n.id == id) return &n;
  return nullptr;
}

}  // namespace

TEST(GraphParts, OnePartIncludedTwiceUnderTwoNamespacesRunsAsTwo) {
  PartFiles files("twice");
  files.write("parts/scaler.yaml", kScaler);
  files.write("g.yaml", R"(include:
  - {part: parts/scaler.yaml, as: double}
  - {part: parts/scaler.yaml, as: triple, args: {factor: 3.0}}
nodes:
  - {id: src, type: counter_source, params: {rate_hz: 10, count: 4}}
  - {id: twice, type: collector}
  - {id: thrice, type: collector}
connections:
  - {from: src.out, to: double.numbers}
  - {from: src.out, to: triple.numbers}
  - {from: double.scaled, to: twice.in}
  - {from: triple.scaled, to: thrice.in}
)");
  const auto r = files.build("g.yaml");
  ASSERT_TRUE(r.graph) << r.diagnostics.str();
  ASSERT_NE(node_named(*r.graph, "double/scale"), nullptr);
  ASSERT_NE(node_named(*r.graph, "triple/relay"), nullptr);
  EXPECT_EQ(node_named(*r.graph, "double/scale")->params.get<double>("factor"), 2.0);  // the arg's default
  EXPECT_EQ(node_named(*r.graph, "triple/scale")->params.get<double>("factor"), 3.0);
  EXPECT_THAT(node_named(*r.graph, "triple/scale")->where.str(), HasSubstr("scaler.yaml:10:5"));
  RunOptions options;
  options.duration_s = 1.0;
  const auto run = run_graph(*r.graph, test_plugins().registry(), options);
  EXPECT_EQ(received(run, "twice"), (std::vector<double>{0, 2, 4, 6}));
  EXPECT_EQ(received(run, "thrice"), (std::vector<double>{0, 3, 6, 9}));
  EXPECT_EQ(connection_stats(run, "src.out -> triple/scale.in").delivered, 4u);
}

TEST(GraphParts, ConnectingToANodeInsideAPartIsRefusedNamingItsPorts) {
  PartFiles files("inside");
  files.write("parts/scaler.yaml", kScaler);
  files.write("g.yaml", R"(include:
  - {part: parts/scaler.yaml, as: front}
nodes:
  - {id: src, type: counter_source}
  - {id: sink, type: collector}
connections:
  - {from: src.out, to: front/scale.in}
  - {from: front.scale, to: sink.in}
)");
  const auto r = files.build("g.yaml");
  EXPECT_FALSE(r.graph);
  const std::string all = r.diagnostics.str();
  EXPECT_THAT(all,
              HasSubstr(files.path("g.yaml") + ":7:25: error: 'front/scale' is inside part 'front' (" +
                        files.path("parts/scaler.yaml") +
                        "): a connection reaches a part only through its ports (inputs: numbers; outputs: scaled)"));
  EXPECT_THAT(
      all, HasSubstr(":8:12: error: part 'front' (" + files.path("parts/scaler.yaml") +
                     ") has no output 'scale' (did you mean 'scaled'?); its ports: inputs: numbers; outputs: scaled"));
}

TEST(GraphParts, ArgsAreCheckedAndTheCommandLineReachesInsideByTheFullName) {
  PartFiles files("args");
  files.write("parts/scaler.yaml", kScaler);
  files.write("parts/needs.yaml", R"(part: needs
args:
  factor: {description: no default, to: scale.factor}
  ghost: {default: 1, to: nowhere.factor}
  typo: {default: 1, to: scale.fctor}
inputs: {numbers: scale.in}
outputs: {scaled: scale.out}
nodes:
  - {id: scale, type: scale}
)");
  files.write("g.yaml", R"(include:
  - {part: parts/scaler.yaml, as: a, args: {factr: 3.0}}
  - {part: parts/needs.yaml, as: b}
nodes:
  - {id: src, type: counter_source}
  - {id: sink, type: collector}
  - {id: sink2, type: collector}
connections:
  - {from: src.out, to: a.numbers}
  - {from: src.out, to: b.numbers}
  - {from: a.scaled, to: sink.in}
  - {from: b.scaled, to: sink2.in}
)");
  const auto r = files.build("g.yaml");
  EXPECT_FALSE(r.graph);
  const std::string all = r.diagnostics.str();
  EXPECT_THAT(all, HasSubstr(":2:45: error: part 'a' (" + files.path("parts/scaler.yaml") +
                             ") has no arg 'factr' (did you mean 'factor'?); its args: factor"));
  EXPECT_THAT(all, HasSubstr(files.path("g.yaml") + ":3:5: error: part 'b' (" + files.path("parts/needs.yaml") +
                             ") needs arg 'factor' (no default)"));
  EXPECT_THAT(
      all, HasSubstr(files.path("parts/needs.yaml") + ":4:27: error: arg 'ghost' sets 'nowhere.factor', but part 'b'"));
  EXPECT_THAT(all,
              HasSubstr(files.path("parts/needs.yaml") +
                        ":5:19: error: node 'b/scale' (scale): unknown parameter 'fctor' (did you mean 'factor'?)"));

  // Given, the args set the parameters; --set with the full name wins over them.
  files.write("g2.yaml", R"(include:
  - {part: parts/scaler.yaml, as: a, args: {factor: 5.0}}
nodes:
  - {id: src, type: counter_source}
  - {id: sink, type: collector}
connections:
  - {from: src.out, to: a.numbers}
  - {from: a.scaled, to: sink.in}
)");
  auto ok = files.build("g2.yaml");
  ASSERT_TRUE(ok.graph) << ok.diagnostics.str();
  EXPECT_EQ(node_named(*ok.graph, "a/scale")->params.get<double>("factor"), 5.0);
  ok = files.build("g2.yaml", {"a/scale.factor=7"});
  ASSERT_TRUE(ok.graph) << ok.diagnostics.str();
  EXPECT_EQ(node_named(*ok.graph, "a/scale")->params.get<double>("factor"), 7.0);
}

TEST(GraphParts, PartsNestPortsAndArgsPassInwards) {
  PartFiles files("nest");
  files.write("parts/scaler.yaml", kScaler);
  // Two scalers in a row; the outer part's input feeds the first and a monitor at once.
  files.write("parts/chain.yaml", R"(part: chain
inputs:
  numbers: {to: [first.numbers, seen.in]}
outputs:
  out: second.scaled
args:
  gain: {default: 10.0, to: [first.factor, second.factor]}
include:
  - {part: scaler.yaml, as: first}
  - {part: scaler.yaml, as: second}
nodes:
  - {id: seen, type: collector}
connections:
  - {from: first.scaled, to: second.numbers}
)");
  files.write("g.yaml", R"(include:
  - {part: parts/chain.yaml, as: c, args: {gain: 2.0}}
nodes:
  - {id: src, type: counter_source, params: {rate_hz: 10, count: 3}}
  - {id: sink, type: collector}
connections:
  - {from: src.out, to: c.numbers}
  - {from: c.out, to: sink.in}
)");
  const auto r = files.build("g.yaml");
  ASSERT_TRUE(r.graph) << r.diagnostics.str();
  EXPECT_EQ(node_named(*r.graph, "c/first/scale")->params.get<double>("factor"), 2.0);
  EXPECT_EQ(node_named(*r.graph, "c/second/scale")->params.get<double>("factor"), 2.0);
  RunOptions options;
  options.duration_s = 1.0;
  const auto run = run_graph(*r.graph, test_plugins().registry(), options);
  EXPECT_EQ(received(run, "sink"), (std::vector<double>{0, 4, 8}));
  EXPECT_EQ(received(run, "c/seen"), (std::vector<double>{0, 1, 2}));  // the report key follows the namespace
}

TEST(GraphParts, APartIsNoRunnableGraphAndIncludesNothingButParts) {
  PartFiles files("rules");
  files.write("parts/scaler.yaml", kScaler);
  files.write("parts/runnable.yaml", R"(nodes:
  - {id: src, type: counter_source}
)");
  files.write("parts/bad.yaml", R"(part: bad
include:
  - runnable.yaml
nodes:
  - {id: src, type: counter_source}
)");
  files.write("parts/wraps_graph.yaml", R"(part: wraps
include:
  - {part: runnable.yaml, as: g}
nodes:
  - {id: src, type: counter_source}
)");
  files.write("g.yaml", R"(include:
  - parts/scaler.yaml
  - {part: parts/bad.yaml, as: b}
  - {part: parts/wraps_graph.yaml, as: w}
  - {part: parts/scaler.yaml, as: w}
nodes:
  - {id: src, type: counter_source}
)");
  const auto r = files.build("g.yaml");
  EXPECT_FALSE(r.graph);
  const std::string all = r.diagnostics.str();
  EXPECT_THAT(
      all, HasSubstr(files.path("g.yaml") +
                     ":2:5: error: this file is a part: include it with 'part:' and 'as:', and connect to its ports"));
  EXPECT_THAT(all, HasSubstr(files.path("parts/bad.yaml") + ":3:5: error: a part includes only parts"));
  EXPECT_THAT(all, HasSubstr(files.path("parts/wraps_graph.yaml") +
                             ":3:12: error: 'runnable.yaml' is a runnable graph, not a part"));
  EXPECT_THAT(all, HasSubstr(files.path("g.yaml") + ":5:35: error: two parts are included as 'w'"));
  // A part alone is not a graph to run.
  const auto alone = files.build("parts/scaler.yaml");
  EXPECT_FALSE(alone.graph);
  EXPECT_THAT(alone.diagnostics.str(), HasSubstr("this file is a part, not a runnable graph"));
}

TEST(GraphParts, NoPartIsIncludedFromAboveItsIncludersFolder) {
  PartFiles files("up");
  files.write("parts/scaler.yaml", kScaler);
  files.write("parts/up.yaml", R"(part: up
include:
  - {part: ../parts/scaler.yaml, as: s}
)");
  files.write("g.yaml", R"(include:
  - {part: parts/up.yaml, as: u}
  - {part: /parts/scaler.yaml, as: v}
nodes:
  - {id: src, type: counter_source}
)");
  const auto r = files.build("g.yaml");
  EXPECT_FALSE(r.graph);
  const std::string all = r.diagnostics.str();
  EXPECT_THAT(all, HasSubstr(files.path("parts/up.yaml") + ":3:12: error: a part is included from the includer's "
                                                           "folder or below it, not '../parts/scaler.yaml'"));
  EXPECT_THAT(all, HasSubstr(files.path("g.yaml") + ":3:12: error: a part is included from the includer's folder or "
                                                    "below it, not '/parts/scaler.yaml'"));
}

TEST(GraphParts, APortBoundToNothingOrDeclaredWithTheWrongTypeIsAnErrorInThePart) {
  PartFiles files("ports");
  files.write("parts/broken.yaml", R"(part: broken
inputs:
  numbers: {to: scale.input}
  typed: {to: scale.in, type: test.Blob}
outputs:
  out: missing.out
nodes:
  - {id: scale, type: scale}
)");
  files.write("g.yaml", R"(include:
  - {part: parts/broken.yaml, as: p}
nodes:
  - {id: src, type: counter_source}
connections:
  - {from: src.out, to: p.typed}
)");
  const auto r = files.build("g.yaml");
  EXPECT_FALSE(r.graph);
  const std::string all = r.diagnostics.str();
  EXPECT_THAT(all,
              HasSubstr(files.path("parts/broken.yaml") + ":3:17: error: node 'scale' (scale) has no input 'input'"));
  EXPECT_THAT(all,
              HasSubstr(files.path("parts/broken.yaml") +
                        ":4:15: error: the part's input 'typed' is declared test.Blob, but scale.in is test.Number"));
  EXPECT_THAT(all, HasSubstr(files.path("parts/broken.yaml") + ":6:8: error: no node 'missing' in the part 'p'"));
}
