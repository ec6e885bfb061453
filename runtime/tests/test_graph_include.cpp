// Graphs that include other graphs: nodes and connections merge, `set:` changes included
// parameters (and --set wins over it), and every error names the file it is in.
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

// A folder of graph files for one test.
class GraphFiles {
 public:
  explicit GraphFiles(const std::string& name) : dir_(kestrel::testing::scratch_path("kestrel-include-" + name)) {
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "chains");
  }
  ~GraphFiles() { fs::remove_all(dir_); }
  fs::path write(const std::string& name, const std::string& text) const {
    std::ofstream(dir_ / name) << text;
    return dir_ / name;
  }
  BuildResult build(const std::string& name, const std::vector<std::string>& overrides = {}) const {
    return build_graph(GraphSource::from_file(dir_ / name), test_plugins().registry(), overrides);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

 private:
  fs::path dir_;
};

// A source and a relay; the including graph adds the sink.
const char* kChain = R"(name: chain
executor: realtime
nodes:
  - id: src
    type: counter_source
    params: {rate_hz: 10, count: 5}
  - id: relay
    type: relay
connections:
  - {from: src.out, to: relay.in}
)";

}  // namespace

TEST(GraphInclude, MergesNodesAndConnectionsAndKeepsTheIncludingHeader) {
  GraphFiles files("merge");
  files.write("chains/chain.yaml", kChain);
  files.write("g.yaml", R"(name: top
include:
  - chains/chain.yaml
nodes:
  - id: sink
    type: collector
connections:
  - {from: relay.out, to: sink.in}
)");
  const auto r = files.build("g.yaml");
  ASSERT_TRUE(r.graph) << r.diagnostics.str();
  EXPECT_EQ(r.graph->name, "top");
  EXPECT_EQ(r.graph->executor, ExecutorKind::lockstep);  // the included file's 'realtime' is not inherited
  ASSERT_EQ(r.graph->nodes.size(), 3u);
  EXPECT_EQ(r.graph->nodes[0].id, "src");  // included nodes come first, in their order
  EXPECT_EQ(r.graph->nodes[2].id, "sink");
  EXPECT_EQ(r.graph->connections.size(), 2u);
  EXPECT_THAT(r.graph->nodes[0].where.str(), HasSubstr("chain.yaml:4:5"));

  // And it runs: five counts reach the sink through the included relay.
  RunOptions options;
  options.duration_s = 1.0;
  const auto run = run_graph(*r.graph, test_plugins().registry(), options);
  EXPECT_EQ(node_stats(run, "sink").messages_in, 5u);
}

TEST(GraphInclude, SetChangesIncludedParametersAndCommandLineSetWins) {
  GraphFiles files("set");
  files.write("chain.yaml", kChain);
  files.write("g.yaml", R"(include:
  - file: chain.yaml
    set: {src.rate_hz: 20, src.count: 7}
nodes:
  - {id: sink, type: collector}
connections:
  - {from: relay.out, to: sink.in}
)");
  auto r = files.build("g.yaml");
  ASSERT_TRUE(r.graph) << r.diagnostics.str();
  EXPECT_EQ(r.graph->nodes[0].params.get<double>("rate_hz"), 20.0);
  EXPECT_EQ(r.graph->nodes[0].params.get<std::int64_t>("count"), 7);
  r = files.build("g.yaml", {"src.count=9"});
  ASSERT_TRUE(r.graph) << r.diagnostics.str();
  EXPECT_EQ(r.graph->nodes[0].params.get<double>("rate_hz"), 20.0);
  EXPECT_EQ(r.graph->nodes[0].params.get<std::int64_t>("count"), 9);
}

TEST(GraphInclude, ErrorsNameTheFileTheyAreIn) {
  GraphFiles files("errors");
  std::string broken = kChain;
  broken.replace(broken.find("rate_hz: 10"), 11, "rate_hz: -1");
  files.write("chain.yaml", broken);
  files.write("g.yaml", R"(include:
  - file: chain.yaml
    set: {src.rate_hs: 3}
nodes:
  - {id: relay, type: collector}
connections:
  - {from: relay.out, to: relay.in}
)");
  const auto r = files.build("g.yaml");
  EXPECT_FALSE(r.graph);
  const std::string all = r.diagnostics.str();
  // The bad value is in the included file; the bad key and the duplicate id are in g.yaml.
  EXPECT_THAT(all,
              HasSubstr(files.path("chain.yaml") + ":6:23: error: node 'src' (counter_source): parameter 'rate_hz'"));
  EXPECT_THAT(
      all, HasSubstr(files.path("g.yaml") + ":3:11: error: node 'src' (counter_source): unknown parameter 'rate_hs'"));
  EXPECT_THAT(all, HasSubstr(files.path("g.yaml") + ":5:10: error: duplicate node id 'relay' (first defined at " +
                             files.path("chain.yaml") + ":7:5)"));
}

TEST(GraphInclude, MissingFilesCyclesAndBadEntriesAreReported) {
  GraphFiles files("refusals");
  files.write("a.yaml", "include: [b.yaml]\nnodes:\n  - {id: a, type: collector}\n");
  files.write("b.yaml", "include: [a.yaml]\nnodes:\n  - {id: b, type: collector}\n");
  auto r = files.build("a.yaml");
  EXPECT_FALSE(r.graph);
  EXPECT_THAT(r.diagnostics.str(),
              HasSubstr(files.path("b.yaml") + ":1:11: error: 'a.yaml' is already being included"));

  files.write("g.yaml", "include:\n  - nowhere.yaml\n  - {file: a.yaml, sett: {}}\n  - [x]\nnodes: []\n");
  r = files.build("g.yaml");
  EXPECT_FALSE(r.graph);
  const std::string all = r.diagnostics.str();
  EXPECT_THAT(all, HasSubstr(files.path("g.yaml") + ":2:5: error: included graph file"));
  EXPECT_THAT(all, HasSubstr("does not exist"));
  EXPECT_THAT(all, HasSubstr(files.path("g.yaml") + ":3:20: error: unknown key 'sett' in an include; keys: file, set"));
  EXPECT_THAT(all, HasSubstr(files.path("g.yaml") + ":4:5: error: an include is a graph file name"));
}

// Only regular files are read: including a device, a pipe or a folder is an error, not a hang.
TEST(GraphInclude, AnIncludeMustBeARegularFile) {
  GraphFiles files("not-regular");
  files.write("g.yaml", "include: [/dev/zero, chains]\nnodes:\n  - {id: a, type: collector}\n");
  const auto r = files.build("g.yaml");
  EXPECT_FALSE(r.graph);
  const std::string all = r.diagnostics.str();
  EXPECT_THAT(all,
              HasSubstr(files.path("g.yaml") + ":1:11: error: included graph file '/dev/zero' is not a regular file"));
  EXPECT_THAT(all, HasSubstr(files.path("chains") + "' is not a regular file"));
}

// A name the file system refuses (longer than NAME_MAX here) is a diagnostic, not an exception.
TEST(GraphInclude, NamesTheFileSystemRefusesAreErrors) {
  GraphFiles files("long-names");
  const std::string long_name(300, 'a');
  const auto missing = GraphSource::from_file(files.path(long_name + ".yaml"));
  EXPECT_THAT(missing.read_errors().str(), HasSubstr("error: cannot read the graph file: File name too long"));
  files.write("g.yaml", "include: [" + long_name + ".yaml]\nnodes:\n  - {id: a, type: collector}\n");
  const auto r = files.build("g.yaml");
  EXPECT_FALSE(r.graph);
  EXPECT_THAT(r.diagnostics.str(), HasSubstr(files.path("g.yaml") + ":1:11: error: cannot read included graph file"));
}

TEST(GraphInclude, AnInputConnectedInTwoFilesIsRefused) {
  GraphFiles files("twice");
  files.write("chain.yaml", kChain);
  files.write("g.yaml", R"(include: [chain.yaml]
nodes:
  - {id: other, type: counter_source}
connections:
  - {from: other.out, to: relay.in}
)");
  const auto r = files.build("g.yaml");
  EXPECT_FALSE(r.graph);
  EXPECT_THAT(r.diagnostics.str(),
              HasSubstr(files.path("g.yaml") + ":5:27: error: input relay.in is already connected (" +
                        files.path("chain.yaml") + ":10:5)"));
}
