// kestrel sweep and kestrel ab on short runs of a tracking graph. The graphs are the paper's tracking
// experiment with the detection-level camera (tests/integration/graphs): these test the commands,
// and the rendered chain would cost a minute under ASan for nothing they check.
#include <gmock/gmock.h>
#include <spawn.h>
#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "kestrel/testing/scratch_path.hpp"

extern char** environ;
namespace fs = std::filesystem;

namespace {

const std::string kTracking = KESTREL_SOURCE_DIR "/tests/integration/graphs/tracking_detection_level.yaml";
const std::string kTrackingParticle =
    KESTREL_SOURCE_DIR "/tests/integration/graphs/tracking_detection_level_particle.yaml";

int run_kestrel(std::vector<std::string> args) {
  std::string cli = KESTREL_CLI;
  std::vector<char*> argv = {cli.data()};
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = -1;
  if (posix_spawn(&pid, cli.c_str(), nullptr, nullptr, argv.data(), environ) != 0) return -1;
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string read(const fs::path& f) {
  std::ifstream in(f);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace

TEST(Experiments, SweepRunsTheGridWithEverySeed) {
  const fs::path dir = kestrel::testing::scratch_path("kestrel-sweep-test");
  fs::remove_all(dir);
  ASSERT_EQ(run_kestrel({"sweep", kTracking, "--param", "tracker.filter.r=0.5:1.0:0.5", "--seeds", "2", "--duration",
                         "0.5", "--report", dir.string()}),
            0);
  const std::string csv = read(dir / "sweep.csv");
  EXPECT_THAT(csv, ::testing::StartsWith("tracker.filter.r,seed,exit_code,"));
  EXPECT_THAT(csv, ::testing::HasSubstr("\n0.5,1,0,"));
  EXPECT_THAT(csv, ::testing::HasSubstr("\n1,2,0,"));
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 5);  // header + 2 values x 2 seeds
  EXPECT_TRUE(fs::exists(dir / "sweep.md"));
  EXPECT_TRUE(fs::exists(dir / "sweep.png"));
  EXPECT_TRUE(fs::exists(dir / "metrics_meta.json"));  // units for `kestrel plot sweep.csv`
  EXPECT_TRUE(fs::exists(dir / "runs" / "001_seed2" / "report.json"));
  // A bad parameter fails before any run, as an invalid graph.
  EXPECT_EQ(run_kestrel({"sweep", kTracking, "--param", "tracker.rr=0.5:1:0.5", "--report", (dir / "bad").string()}),
            3);
  EXPECT_FALSE(fs::exists(dir / "bad" / "runs"));
}

// A table of cases instead of a grid: each row once with its seed, an empty cell leaving the
// graph's value; a row with a value out of range stops the sweep before any run.
TEST(Experiments, SweepRunsATableOfCasesWithTheirSeeds) {
  const fs::path dir = kestrel::testing::scratch_path("kestrel-sweep-cases-test");
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "cases.csv") << "# tracker settings drawn at random\n"
                                      "tracker.filter.r,tracker.filter.q,seed\n"
                                      "0.5,,3\n"
                                      "\"2.0\",0.5,5\n";
  ASSERT_EQ(run_kestrel({"sweep", kTracking, "--cases", (dir / "cases.csv").string(), "--duration", "0.5", "--report",
                         (dir / "out").string()}),
            0);
  const std::string csv = read(dir / "out" / "sweep.csv");
  EXPECT_THAT(csv, ::testing::StartsWith("tracker.filter.r,tracker.filter.q,seed,exit_code,"));
  EXPECT_THAT(csv, ::testing::HasSubstr("\n0.5,,3,0,"));
  EXPECT_THAT(csv, ::testing::HasSubstr("\n2.0,0.5,5,0,"));
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 3);  // header + one run per case
  EXPECT_THAT(read(dir / "out" / "sweep.md"), ::testing::HasSubstr("2 cases from " + (dir / "cases.csv").string()));
  EXPECT_TRUE(fs::exists(dir / "out" / "sweep.png"));
  // Each run got its case's values and seed; an empty cell left the graph's q (200).
  const auto first = nlohmann::json::parse(read(dir / "out" / "runs" / "000_seed3" / "report.json")).at("graph");
  const auto second = nlohmann::json::parse(read(dir / "out" / "runs" / "001_seed5" / "report.json")).at("graph");
  EXPECT_EQ(first.at("seed"), 3);
  EXPECT_EQ(second.at("seed"), 5);
  const auto filter = [](const nlohmann::json& graph) {
    return graph.at("resolved").at("nodes").at("tracker").at("params").at("filter").at("params");
  };
  EXPECT_EQ(filter(first).at("r"), 0.5);
  EXPECT_EQ(filter(first).at("q"), 200.0);
  EXPECT_EQ(filter(second).at("r"), 2.0);
  EXPECT_EQ(filter(second).at("q"), 0.5);
  // Every case is checked first, not only the first and the last: the second row's r is out of
  // range, so nothing runs.
  std::ofstream(dir / "bad.csv") << "tracker.filter.r,seed\n1.0,1\n-1,2\n2.0,3\n";
  EXPECT_EQ(run_kestrel({"sweep", kTracking, "--cases", (dir / "bad.csv").string(), "--duration", "0.5", "--report",
                         (dir / "bad").string()}),
            3);
  EXPECT_FALSE(fs::exists(dir / "bad" / "runs"));
}

TEST(Experiments, AbPairsSeedsAndNamesTheBetterGraph) {
  const fs::path dir = kestrel::testing::scratch_path("kestrel-ab-test");
  fs::remove_all(dir);
  ASSERT_EQ(
      run_kestrel({"ab", kTracking, kTrackingParticle, "--seeds", "2", "--duration", "1", "--report", dir.string()}),
      0);
  const auto ab = nlohmann::json::parse(read(dir / "ab.json"));
  EXPECT_EQ(ab.at("seeds"), 2);
  // Same detections on both sides (same seeds, same chain): only the tracker differs.
  EXPECT_EQ(ab.at("metrics").at("detection.recall").at("better"), "equal");
  // Every metric of both reports is compared; a verdict only where metrics_meta gives a direction
  // (the verdicts themselves are tested on known data in test_ab_verdicts.cpp).
  ASSERT_TRUE(ab.at("metrics_meta").is_object());
  EXPECT_TRUE(ab.at("metrics").contains("tracking.num_objects"));
  for (const auto& [metric, row] : ab.at("metrics").items()) {
    const auto& better = row.at("better");
    if (better.is_null()) {
      EXPECT_FALSE(ab.at("metrics_meta").contains(metric) &&
                   ab.at("metrics_meta").at(metric).contains("higher_is_better"))
          << metric;
    } else {
      EXPECT_THAT(better.get<std::string>(), ::testing::AnyOf("A", "B", "equal", "no significant difference"))
          << metric;
    }
  }
  EXPECT_THAT(read(dir / "ab.md"), ::testing::HasSubstr("| tracking.mota |"));
  // The metrics that differ, seed by seed, as a picture.
  EXPECT_TRUE(fs::exists(dir / "ab.png"));
  EXPECT_THAT(read(dir / "ab.md"), ::testing::HasSubstr("![A and B seed by seed](ab.png)"));
}

// One graph on both sides, a parameter changed on one: the A/B of a single tracker setting.
TEST(Experiments, AbComparesSettingsOfOneGraph) {
  const fs::path dir = kestrel::testing::scratch_path("kestrel-ab-settings-test");
  fs::remove_all(dir);
  ASSERT_EQ(run_kestrel({"ab", kTracking, kTracking, "--set-a", "tracker.filter.r=0.1", "--set-b",
                         "tracker.filter.r=5.0", "--seeds", "2", "--duration", "1", "--report", dir.string()}),
            0);
  const auto ab = nlohmann::json::parse(read(dir / "ab.json"));
  EXPECT_EQ(ab.at("set_a"), nlohmann::json::array({"tracker.filter.r=0.1"}));
  EXPECT_EQ(ab.at("set_b"), nlohmann::json::array({"tracker.filter.r=5.0"}));
  EXPECT_EQ(ab.at("metrics").at("detection.recall").at("better"), "equal");
  const auto& rmse = ab.at("metrics").at("tracking.rmse_m");
  EXPECT_NE(rmse.at("mean_a").get<double>(), rmse.at("mean_b").get<double>());
  EXPECT_THAT(read(dir / "ab.md"), ::testing::HasSubstr("with tracker.filter.r=5.0"));
  // An override one side's graph does not accept fails before any run, as an invalid graph.
  EXPECT_EQ(
      run_kestrel({"ab", kTracking, kTracking, "--set-b", "tracker.particles=10", "--report", (dir / "bad").string()}),
      3);
  EXPECT_FALSE(fs::exists(dir / "bad" / "runs"));
}

// `kestrel mot` and the mot_evaluator node name the CLEAR-MOT figures alike: every number in a
// real "tracking" section is in `kestrel mot --json` too, but for the figures of the selected
// track and of time, which MOTChallenge files do not have, and the count of messages the node
// could not pair with ground truth.
TEST(Experiments, MotCommandAndMotEvaluatorShareTheirKeys) {
  const fs::path dir = kestrel::testing::scratch_path("kestrel-mot-keys-test");
  fs::remove_all(dir);
  fs::create_directories(dir);
  ASSERT_EQ(run_kestrel({"run", kTracking, "--duration", "0.5", "--report", (dir / "run").string(), "--no-progress"}),
            0);
  const auto tracking = nlohmann::json::parse(read(dir / "run" / "report.json")).at("tracking");
  std::ofstream(dir / "gt.txt") << "1,1,0,0,10,10,1,0,0,5\n2,1,0,0,10,10,1,0,0,5\n";
  ASSERT_EQ(run_kestrel({"mot", (dir / "gt.txt").string(), (dir / "gt.txt").string(), "--dist", "0.5", "--json",
                         (dir / "mot.json").string()}),
            0);
  const auto mot = nlohmann::json::parse(read(dir / "mot.json"));
  const std::set<std::string> tracker_only = {"rmse_m", "rmse_axes_m",     "rmse_body_m", "bias_body_m",
                                              "lag_s",  "selected_frames", "target",      "unpaired"};
  for (const auto& [key, value] : tracking.items()) {
    if (tracker_only.count(key)) continue;
    EXPECT_TRUE(mot.contains(key)) << "kestrel mot --json has no '" << key << "'";
  }
}
