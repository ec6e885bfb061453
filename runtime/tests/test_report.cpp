// report.json says what ran (resolved parameters, graph hash, version, seed), how to read its
// metrics (metrics_meta), and lists the files nodes added through the report.
#include <gmock/gmock.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "kestrel/testing/graphs.hpp"
#include "kestrel/testing/scratch_path.hpp"
#include "kestrel/version.hpp"

using namespace kestrel;
using namespace kestrel::testing;
using ::testing::HasSubstr;

namespace {

const char* kGraph = R"(name: report
duration: 1
seed: 7
nodes:
  - id: src
    type: counter_source
    params: {rate_hz: 10}
  - id: s
    type: shape
  - id: sink
    type: collector
connections:
  - {from: src.out, to: s.in}
  - {from: s.out, to: sink.in}
)";

nlohmann::json run_and_read(const std::filesystem::path& dir, const std::vector<std::string>& overrides) {
  std::filesystem::remove_all(dir);
  auto built = build(kGraph, overrides);
  EXPECT_TRUE(built.graph) << built.diagnostics.str();
  RunOptions options;
  options.report_dir = dir;
  run_graph(*built.graph, test_plugins().registry(), options);
  std::ifstream in(dir / "report.json");
  return nlohmann::json::parse(in);
}

std::string read(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

TEST(Report, RecordsTheResolvedParametersHashVersionAndSeed) {
  const auto dir = kestrel::testing::scratch_path("kestrel-report-test");
  const auto report = run_and_read(dir, {"src.rate_hz=20", "s.shaper.amount=3"});
  EXPECT_EQ(report["kestrel_version"], KESTREL_VERSION_STRING);
  EXPECT_EQ(report["graph"]["seed"], 7);
  const auto& nodes = report["graph"]["resolved"]["nodes"];
  EXPECT_EQ(nodes["src"]["type"], "counter_source");
  EXPECT_EQ(nodes["src"]["params"]["rate_hz"], 20.0);  // --set applied
  EXPECT_EQ(nodes["src"]["params"]["count"], 0);       // default filled in
  EXPECT_EQ(nodes["s"]["params"]["shaper"]["type"], "offset");
  EXPECT_EQ(nodes["s"]["params"]["shaper"]["params"]["amount"], 3.0);
  EXPECT_EQ(report["graph"]["resolved"]["connections"].size(), 2u);

  // The hash follows what runs, not the file: the same settings give the same hash, another
  // value of one parameter another hash.
  const std::string hash = report["graph"]["hash"];
  EXPECT_THAT(hash, ::testing::StartsWith("fnv1a64:"));
  EXPECT_EQ(run_and_read(dir, {"src.rate_hz=20", "s.shaper.amount=3"})["graph"]["hash"], hash);
  EXPECT_NE(run_and_read(dir, {"src.rate_hz=20", "s.shaper.amount=4"})["graph"]["hash"], hash);
}

TEST(Report, MetricsDescribeThemselvesAndArtifactsAreListed) {
  const auto dir = kestrel::testing::scratch_path("kestrel-report-meta");
  const auto report = run_and_read(dir, {});
  EXPECT_EQ(report["sink"]["count"], 10);
  const auto& meta = report["metrics_meta"]["sink.count"];
  EXPECT_EQ(meta["unit"], "messages");
  EXPECT_EQ(meta["higher_is_better"], true);
  EXPECT_FALSE(meta.contains("by_magnitude"));

  ASSERT_EQ(report["artifacts"].size(), 1u);
  EXPECT_EQ(report["artifacts"][0]["file"], "sink.csv");
  EXPECT_EQ(report["artifacts"][0]["node"], "sink");
  const std::string csv = read(dir / "sink.csv");
  EXPECT_THAT(csv, ::testing::StartsWith("index,value\n0,"));
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 11);
  EXPECT_THAT(read(dir / "report.md"), HasSubstr("[sink.csv](sink.csv): the values received (sink)"));
}

TEST(Report, WithoutAReportFolderArtifactsAreNotWritten) {
  auto built = build(kGraph);
  ASSERT_TRUE(built.graph);
  const auto result = run_graph(*built.graph, test_plugins().registry(), {});
  EXPECT_TRUE(result.report["artifacts"].empty());
}

TEST(Report, ArtifactNamesMustBePlainFileNames) {
  Report report;
  report.set_artifact_dir(std::filesystem::temp_directory_path());
  EXPECT_THROW(report.add_artifact("n", "../escape.csv", "x", ""), Error);
  EXPECT_THROW(report.add_artifact("n", "", "x", ""), Error);
  report.add_artifact("a", "kestrel-owned-by-a.txt", "x", "");
  EXPECT_THROW(report.add_artifact("b", "kestrel-owned-by-a.txt", "y", ""), Error);
}

TEST(ReportSection, EachValueIsSetWithItsUnitAndDirection) {
  ReportSection section;
  section.metric("recall", 0.9, "", Better::higher)
      .metric("rmse_m", {{"x", 0.1}, {"y", 0.2}}, "m", Better::lower)
      .metric("lag_s", -0.02, "s", Better::nearer_zero)
      .quantity("target.frames", 12)
      .info("mode", "fast")
      .markdown("text");
  EXPECT_EQ(section.values()["target"]["frames"], 12);
  EXPECT_EQ(section.values()["rmse_m"]["y"], 0.2);
  EXPECT_EQ(section.values()["mode"], "fast");
  EXPECT_EQ(section.metrics().at("recall"), (MetricMeta{"", true, false}));
  EXPECT_EQ(section.metrics().at("rmse_m"), (MetricMeta{"m", false, false}));
  EXPECT_EQ(section.metrics().at("lag_s"), (MetricMeta{"s", false, true}));
  EXPECT_EQ(section.metrics().at("target.frames"), (MetricMeta{"", std::nullopt, false}));
  EXPECT_FALSE(section.metrics().count("mode"));
  EXPECT_EQ(section.markdown(), "text");
}

TEST(ReportSection, ANumberCannotBeReportedWithoutSayingHowToReadIt) {
  ReportSection section;
  EXPECT_THROW(section.info("count", 3), Error);
  EXPECT_THROW(section.info("position", nlohmann::json::array({1.0, 2.0})), Error);
  EXPECT_THROW(section.info("", "x"), Error);
  section.quantity("count", 3);
  EXPECT_THROW(section.quantity("count.below", 1), Error);  // a number is not a table
}

TEST(ReportSection, TheReportKeysReadingsByTheSectionAndReplacesThemWithIt) {
  Report report;
  ReportSection first;
  first.metric("a", 1, "m", Better::lower).quantity("b", 2);
  report.set_section("node", "sec", first);
  EXPECT_EQ(report.metrics().at("sec.a").unit, "m");
  ReportSection second;
  second.metric("c", 1.0, "", Better::higher);
  report.set_section("node", "sec", second);
  EXPECT_FALSE(report.metrics().count("sec.a"));
  EXPECT_FALSE(report.metrics().count("sec.b"));
  EXPECT_EQ(report.metrics().at("sec.c").higher_is_better, true);
  EXPECT_THROW(report.set_section("other", "sec", second), Error);
  EXPECT_THROW(report.set_section("node", "a.b", second), Error);
}
