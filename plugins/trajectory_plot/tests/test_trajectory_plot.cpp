// The trajectory_plot node. On the test plugin's known scene the CSV holds exactly the samples fed
// in, series by series, and the PNG has one 1000 x 300 panel per axis. Its files go into the
// report, and samples beyond max_samples are counted in the report rather than lost without a word.
#include <gmock/gmock.h>

#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <sstream>

#include "kestrel/runtime/graph.hpp"
#include "kestrel/runtime/plugin_host.hpp"
#include "kestrel/runtime/run.hpp"
#include "kestrel/testing/plugins.hpp"
#include "kestrel/testing/scratch_path.hpp"
#include "test_nodes/scene.hpp"

using namespace kestrel;

namespace {

PluginHost& plugins() { return kestrel::testing::built_and_test_plugins(); }

struct Row {
  std::string series;
  double t, x, y, z;
  bool operator==(const Row&) const = default;
};

void PrintTo(const Row& r, std::ostream* os) {
  *os << r.series << ',' << r.t << ',' << r.x << ',' << r.y << ',' << r.z;
}

std::vector<Row> read_csv(const std::filesystem::path& file, std::string& header) {
  std::ifstream in(file);
  std::getline(in, header);
  std::vector<Row> rows;
  for (std::string line; std::getline(in, line);) {
    std::stringstream fields(line);
    Row r;
    std::string t, x, y, z;
    std::getline(fields, r.series, ',');
    std::getline(fields, t, ',');
    std::getline(fields, x, ',');
    std::getline(fields, y, ',');
    std::getline(fields, z, ',');
    r.t = std::stod(t);
    r.x = std::stod(x);
    r.y = std::stod(y);
    r.z = std::stod(z);
    rows.push_back(r);
  }
  return rows;
}

std::filesystem::path run_plot(const std::string& name, int count, int max_samples) {
  const auto dir = kestrel::testing::scratch_path("kestrel-trajectory-plot-" + name);
  std::filesystem::remove_all(dir);
  const std::string yaml = R"(nodes:
  - {id: scene, type: scene_source, params: {rate_hz: 30, count: )" +
                           std::to_string(count) + R"(, offset_m: [0.1, -0.2, 0.3], miss_every: 4}}
  - {id: plot, type: trajectory_plot, params: {name: )" +
                           name + ", max_samples: " + std::to_string(max_samples) +
                           R"(}}
connections:
  - {from: scene.truth, to: plot.truth}
  - {from: scene.detections, to: plot.detections}
  - {from: scene.tracks, to: plot.tracks}
)";
  auto built = build_graph(GraphSource::from_string(yaml, "g.yaml"), plugins().registry());
  EXPECT_TRUE(built.graph) << built.diagnostics.str();
  if (!built.graph) return dir;
  RunOptions options;
  options.report_dir = dir;
  const auto r = run_graph(*built.graph, plugins().registry(), options);
  EXPECT_EQ(r.outcome, RunOutcome::completed) << (r.errors.empty() ? "" : r.errors.front());
  return dir;
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
std::string intruder_graph(const std::string& plot_params) {
  return R"(nodes:
  - {id: intruder, type: intruder, params: {rate_hz: 30}}
  - {id: plot, type: trajectory_plot, params: )" +
         plot_params + R"(}
connections:
  - {from: intruder.truth, to: plot.truth}
duration: 2.0
)";
}

// What the scene fed in: series in name order, samples in time order.
std::vector<Row> expected_rows(int count, int max_samples) {
  const Eigen::Vector3d offset(0.1, -0.2, 0.3);
  std::vector<Row> detections, track, truth;
  for (int k = 0; k < count; ++k) {
    const double t = to_seconds(from_seconds(static_cast<double>(k) * (1.0 / 30.0)));
    const Eigen::Vector3d p = test::scene_position(k), q = p + offset;
    if (test::scene_detects(k, 4) && static_cast<int>(detections.size()) < max_samples)
      detections.push_back({"detections", t, q.x(), q.y(), q.z()});
    if (static_cast<int>(track.size()) < max_samples) track.push_back({"selected track", t, q.x(), q.y(), q.z()});
    if (static_cast<int>(truth.size()) < max_samples) truth.push_back({"truth 1", t, p.x(), p.y(), p.z()});
  }
  std::vector<Row> all = detections;
  all.insert(all.end(), track.begin(), track.end());
  all.insert(all.end(), truth.begin(), truth.end());
  return all;
}

}  // namespace

TEST(TrajectoryPlot, CsvHoldsExactlyTheSamplesFedInAndPngHasAPanelPerAxis) {
  const auto dir = run_plot("known", 24, 200000);
  std::string header;
  const auto rows = read_csv(dir / "known.csv", header);
  EXPECT_EQ(header, "series,t,x,y,z");
  const auto expected = expected_rows(24, 200000);
  ASSERT_EQ(expected.size(), 18u + 24u + 24u);  // every fourth frame without a detection
  EXPECT_THAT(rows, ::testing::ElementsAreArray(expected));

  const cv::Mat png = cv::imread((dir / "known.png").string());
  ASSERT_FALSE(png.empty());
  EXPECT_EQ(png.cols, 1000);
  EXPECT_EQ(png.rows, 3 * 300);
}

TEST(TrajectoryPlot, KeepsAtMostMaxSamplesPerSeries) {
  const auto dir = run_plot("bounded", 24, 5);
  std::string header;
  EXPECT_THAT(read_csv(dir / "bounded.csv", header), ::testing::ElementsAreArray(expected_rows(24, 5)));
}

TEST(TrajectoryPlot, SamplesBeyondTheLimitAreCountedInTheReport) {
  const auto dir = kestrel::testing::scratch_path("kestrel-plot-dropped");
  const RunResult r = run(intruder_graph("{name: cut, max_samples: 50}"), dir);
  ASSERT_EQ(r.outcome, RunOutcome::completed);
  const auto& section = r.report.at("plot");
  EXPECT_EQ(section.at("samples"), 50);
  EXPECT_EQ(section.at("dropped_samples"), 10);
  std::ifstream md(dir / "report.md");
  const std::string text{std::istreambuf_iterator<char>(md), std::istreambuf_iterator<char>()};
  EXPECT_THAT(text, ::testing::HasSubstr("10 later samples dropped beyond max_samples = 50 per series: truth 1 (10)"));
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
  const auto dir = kestrel::testing::scratch_path("kestrel-plot-kept");
  const RunResult r = run(intruder_graph("{}"), dir);
  ASSERT_EQ(r.outcome, RunOutcome::completed);
  EXPECT_EQ(r.report.at("plot").at("samples"), 60);
  EXPECT_EQ(r.report.at("plot").at("dropped_samples"), 0);
  EXPECT_EQ(lines(dir / "trajectory.csv"), 61);
}

// output_dir was removed: the files go to the report folder, and a graph that still names it is
// refused where it does.
TEST(TrajectoryPlot, TheRemovedOutputFolderIsRefused) {
  const auto built =
      build_graph(GraphSource::from_string(intruder_graph("{output_dir: plots}"), "plot.yaml"), plugins().registry());
  EXPECT_FALSE(built.graph);
  EXPECT_THAT(built.diagnostics.str(), ::testing::HasSubstr("output_dir"));
}
