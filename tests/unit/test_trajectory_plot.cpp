// The trajectory plot in a graph: its files go into the report, and samples beyond max_samples
// are counted in the report rather than lost without a word.
#include <gmock/gmock.h>

#include <filesystem>
#include <fstream>

#include "kestrel/runtime/graph.hpp"
#include "kestrel/runtime/plugin_host.hpp"
#include "kestrel/runtime/run.hpp"

using namespace kestrel;

namespace {

PluginHost& plugins() {
  static PluginHost* host = [] {
    auto* h = new PluginHost();
    h->load_search_path();
    return h;
  }();
  return *host;
}

RunResult run(const std::string& yaml, const std::filesystem::path& report_dir) {
  auto built = build_graph(GraphSource::from_string(yaml), plugins().registry());
  EXPECT_TRUE(built.graph) << built.diagnostics.str();
  if (!built.graph) return {};
  std::filesystem::remove_all(report_dir);
  RunOptions options;
  options.report_dir = report_dir;
  return run_graph(*built.graph, plugins().registry(), options);
}

int lines(const std::filesystem::path& file) {
  std::ifstream in(file);
  int n = 0;
  for (std::string line; std::getline(in, line);) ++n;
  return n;
}

// 2 s of truth at 30 Hz: 60 samples of one series.
std::string graph(const std::string& plot_params) {
  return R"(nodes:
  - {id: intruder, type: intruder, params: {rate_hz: 30}}
  - {id: plot, type: trajectory_plot, params: )" +
         plot_params + R"(}
connections:
  - {from: intruder.truth, to: plot.truth}
duration: 2.0
)";
}

}  // namespace

TEST(TrajectoryPlot, SamplesBeyondTheLimitAreCountedInTheReport) {
  const auto dir = std::filesystem::temp_directory_path() / "kestrel-plot-dropped";
  const RunResult r = run(graph("{name: cut, max_samples: 50}"), dir);
  ASSERT_EQ(r.outcome, RunOutcome::completed);
  const auto& section = r.report.at("plot");
  EXPECT_EQ(section.at("samples"), 50);
  EXPECT_EQ(section.at("dropped_samples"), 10);
  EXPECT_EQ(section.at("series").at("truth 1").at("dropped_samples"), 10);
  EXPECT_EQ(r.report.at("metrics_meta").at("plot.dropped_samples").at("higher_is_better"), false);
  EXPECT_FALSE(r.report.at("metrics_meta").at("plot.samples").contains("higher_is_better"));  // a count
  EXPECT_EQ(lines(dir / "cut.csv"), 51);                                                      // header + the 50 kept
  EXPECT_TRUE(std::filesystem::exists(dir / "cut.png"));
  // The files are listed in the report, with the loss in their caption.
  bool listed = false;
  for (const auto& a : r.report.at("artifacts"))
    if (a.at("file") == "cut.png") {
      listed = true;
      EXPECT_THAT(a.at("caption").get<std::string>(), ::testing::HasSubstr("10 later samples dropped"));
    }
  EXPECT_TRUE(listed);
}

TEST(TrajectoryPlot, NothingDroppedUnderTheLimit) {
  const auto dir = std::filesystem::temp_directory_path() / "kestrel-plot-kept";
  const RunResult r = run(graph("{}"), dir);
  ASSERT_EQ(r.outcome, RunOutcome::completed);
  EXPECT_EQ(r.report.at("plot").at("samples"), 60);
  EXPECT_EQ(r.report.at("plot").at("dropped_samples"), 0);
  EXPECT_EQ(lines(dir / "trajectory.csv"), 61);
}

TEST(TrajectoryPlot, TheOldOutputFolderIsIgnoredAndNothingIsWrittenThere) {
  const auto dir = std::filesystem::temp_directory_path() / "kestrel-plot-report";
  const auto old = std::filesystem::temp_directory_path() / "kestrel-plot-old-folder";
  std::filesystem::remove_all(old);
  const RunResult r = run(graph("{output_dir: " + old.string() + "}"), dir);
  ASSERT_EQ(r.outcome, RunOutcome::completed);
  EXPECT_TRUE(std::filesystem::exists(dir / "trajectory.png"));
  EXPECT_FALSE(std::filesystem::exists(old));
}
