// The kestrel command line: exit codes, reports, and clean shutdown on SIGINT and SIGTERM.
#include <fcntl.h>
#include <gmock/gmock.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "kestrel/testing/graphs.hpp"
#include "kestrel/testing/read_file.hpp"
#include "kestrel/testing/scratch_path.hpp"
#include "live_endpoint.hpp"

extern char** environ;

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;

using kestrel::testing::read_file;

namespace {

// Three numbers from a source to a sink: the smallest graph that runs.
constexpr const char* kCountToThree = R"(nodes:
  - {id: src, type: counter_source, params: {count: 3}}
  - {id: sink, type: collector}
connections:
  - {from: src.out, to: sink.in}
)";

fs::path temp_dir(const std::string& name) {
  const fs::path dir = kestrel::testing::scratch_path("kestrel-cli-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

fs::path write_graph(const fs::path& dir, const std::string& yaml) {
  const fs::path file = dir / "graph.yaml";
  std::ofstream(file) << "plugin_paths: [" << KESTREL_TEST_PLUGIN_DIR << "]\n" << yaml;
  return file;
}

struct Process {
  pid_t pid = -1;
  fs::path output;
};

// Starts the CLI with stdout and stderr sent to a file.
Process start(const std::vector<std::string>& args, const fs::path& output) {
  std::vector<char*> argv;
  std::string cli = KESTREL_CLI;
  argv.push_back(cli.data());
  std::vector<std::string> copy = args;
  for (auto& a : copy) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, output.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  Process p;
  p.output = output;
  EXPECT_EQ(posix_spawn(&p.pid, cli.c_str(), &actions, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&actions);
  return p;
}

int wait_exit(const Process& p) {
  int status = 0;
  waitpid(p.pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

// Waits until the process's output holds `line` (true), or the process has exited or the time is
// up (false). The process is not reaped: wait_exit() still gets its status.
bool wait_for_line(const Process& p, const std::string& line, std::chrono::seconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < deadline) {
    if (read_file(p.output).find(line) != std::string::npos) return true;
    siginfo_t info{};
    if (waitid(P_PID, static_cast<id_t>(p.pid), &info, WEXITED | WNOHANG | WNOWAIT) == 0 && info.si_pid != 0)
      return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

int run_cli(const std::vector<std::string>& args, std::string* output = nullptr) {
  const fs::path out = temp_dir("out") / "output.txt";
  const int code = wait_exit(start(args, out));
  if (output) *output = read_file(out);
  return code;
}

const char* kRealtimeForever = R"(executor: realtime
nodes:
  - {id: src, type: counter_source, params: {rate_hz: 100}}
  - {id: slow, type: slow, params: {delay_ms: 1}}
  - {id: sink, type: collector}
connections:
  - {from: src.out, to: slow.in, policy: fifo 1000}
  - {from: slow.out, to: sink.in, policy: block 4}
)";

// Live processes (not zombies) whose command line contains `needle`.
std::vector<pid_t> processes_with(const std::string& needle) {
  std::vector<pid_t> found;
  for (const auto& entry : fs::directory_iterator("/proc")) {
    const std::string name = entry.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    // A process may exit between the listing and the reads: libstdc++ then throws ESRCH from
    // the stream, and the process is simply no longer there.
    std::string cmdline, stat;
    try {
      cmdline = read_file(entry.path() / "cmdline");
      stat = read_file(entry.path() / "stat");
    } catch (const std::exception&) {
      continue;
    }
    std::replace(cmdline.begin(), cmdline.end(), '\0', ' ');
    const auto state = stat.rfind(')');
    if (state == std::string::npos || state + 2 >= stat.size() || stat[state + 2] == 'Z') continue;
    if (cmdline.find(needle) != std::string::npos) found.push_back(std::stoi(name));
  }
  return found;
}

// True once the process has a handler for the signal (its SigCgt mask in /proc).
bool catches(pid_t pid, int sig) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("SigCgt:", 0) == 0) return (std::stoull(line.substr(7), nullptr, 16) >> (sig - 1)) & 1u;
  return false;
}

// Waits up to `seconds` for the process to exit; kills it if it does not (returns -1 then).
int wait_exit_within(const Process& p, double seconds) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  int status = 0;
  while (waitpid(p.pid, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() > deadline) {
      kill(p.pid, SIGKILL);
      waitpid(p.pid, &status, 0);
      return -1;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace

class CleanShutdown : public ::testing::TestWithParam<int> {};

TEST_P(CleanShutdown, SignalDrainsFlushesAndExitsZero) {
  const fs::path dir = temp_dir("signal" + std::to_string(GetParam()));
  const fs::path graph = write_graph(dir, kRealtimeForever);
  Process p = start({"run", graph.string(), "--report", (dir / "report").string(), "--stats"}, dir / "output.txt");
  // The run says when it is under way: every source has ticked at least once.
  if (!wait_for_line(p, "[kestrel] running", std::chrono::seconds(60))) {
    kill(p.pid, SIGKILL);
    wait_exit(p);
    FAIL() << "the run never said it was running:\n" << read_file(p.output);
  }
  ASSERT_EQ(kill(p.pid, GetParam()), 0);
  EXPECT_EQ(wait_exit(p), 0) << read_file(p.output);
  const auto report = nlohmann::json::parse(read_file(dir / "report" / "report.json"));
  EXPECT_EQ(report.at("outcome"), "stopped");
  // The sink's finish() ran after the queues drained: it saw every message the source sent.
  std::uint64_t sent = 0;
  for (const auto& n : report.at("stats").at("nodes"))
    if (n.at("id") == "src") sent = n.at("messages_out");
  EXPECT_GT(sent, 0u);  // the source had ticked before the signal
  EXPECT_EQ(report.at("sink").at("count"), sent);
  EXPECT_THAT(read_file(p.output), HasSubstr("src.out -> slow.in"));  // --stats printed
  EXPECT_TRUE(fs::exists(dir / "report" / "report.md"));
}

INSTANTIATE_TEST_SUITE_P(Signals, CleanShutdown, ::testing::Values(SIGINT, SIGTERM));

// A sweep stopped by a signal stops its runs (each drains and writes its report), waits for
// them and exits with 128 + the signal: no `kestrel run` is left behind.
class InterruptedSweep : public ::testing::TestWithParam<int> {};

TEST_P(InterruptedSweep, StopsItsRunsAndLeavesNoneBehind) {
  const fs::path dir = temp_dir("sweep-signal" + std::to_string(GetParam()));
  const fs::path graph = write_graph(dir, kRealtimeForever);
  const fs::path runs = dir / "sweep" / "runs";
  Process p = start({"sweep", graph.string(), "--param", "src.rate_hz=100:200:100", "--jobs", "2", "--report",
                     (dir / "sweep").string()},
                    dir / "output.txt");
  // Both runs (realtime, no duration: they would run for ever) are under way, their signal
  // handlers in place (before that, a stopped run has no report to write).
  auto running = [&] {
    const auto pids = processes_with(runs.string());
    return pids.size() == 2 && std::all_of(pids.begin(), pids.end(), [](pid_t pid) { return catches(pid, SIGTERM); });
  };
  for (int i = 0; i < 600 && !running(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  ASSERT_TRUE(running()) << read_file(p.output);
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  ASSERT_EQ(kill(p.pid, GetParam()), 0);
  const int code = wait_exit_within(p, 60);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  const auto survivors = processes_with(runs.string());
  for (const pid_t pid : survivors) kill(pid, SIGKILL);  // leave nothing running, pass or fail
  EXPECT_TRUE(survivors.empty()) << survivors.size() << " run(s) survived the sweep";
  EXPECT_EQ(code, 128 + GetParam()) << read_file(p.output);
  EXPECT_THAT(read_file(p.output), HasSubstr("interrupted"));
  for (const char* run : {"000_seed1", "001_seed1"}) {
    const auto report = nlohmann::json::parse(read_file(runs / run / "report.json"), nullptr, false);
    EXPECT_EQ(report.is_object() ? report.value("outcome", "") : "no report", "stopped") << run;
  }
  EXPECT_FALSE(fs::exists(dir / "sweep" / "sweep.csv"));  // a partial sweep is not summarised
}

INSTANTIATE_TEST_SUITE_P(Signals, InterruptedSweep, ::testing::Values(SIGINT, SIGTERM));

TEST(Cli, ExitCodes) {
  const fs::path dir = temp_dir("codes");
  std::string out;
  EXPECT_EQ(run_cli({"--help"}), 0);
  EXPECT_EQ(run_cli({"run", "--help"}), 0);
  EXPECT_EQ(run_cli({"frobnicate"}), 2);
  EXPECT_EQ(run_cli({"run"}), 2);
  EXPECT_EQ(run_cli({"validate", (dir / "missing.yaml").string()}, &out), 3);
  EXPECT_THAT(out, HasSubstr("missing.yaml: error: no such graph file"));

  const fs::path bad = write_graph(dir, "nodes:\n  - {id: a, type: relai}\n");
  EXPECT_EQ(run_cli({"validate", bad.string()}, &out), 3);
  EXPECT_THAT(out, HasSubstr("graph.yaml:3:19: error: unknown node type 'relai' (did you mean 'relay'?)"));
  EXPECT_EQ(run_cli({"run", bad.string()}, &out), 3);
  EXPECT_THAT(out, HasSubstr("the graph was not run"));

  const fs::path failing = write_graph(dir, R"(nodes:
  - {id: src, type: counter_source, params: {count: 5}}
  - {id: picky, type: faulty, params: {fail_every: 2}}
  - {id: sink, type: collector}
connections:
  - {from: src.out, to: picky.in}
  - {from: picky.out, to: sink.in}
)");
  EXPECT_EQ(run_cli({"run", failing.string()}, &out), 1);
  EXPECT_THAT(out, HasSubstr("[picky] bad number 1"));
  EXPECT_EQ(run_cli({"run", failing.string(), "--set", "picky.fail_every=0"}), 0);
  EXPECT_EQ(run_cli({"run", failing.string(), "--set", "picky.fail_evry=0"}, &out), 3);
  EXPECT_THAT(out, HasSubstr("did you mean 'fail_every'?"));

  EXPECT_EQ(run_cli({"inspect", "no_such_type"}), 4);
}

// validate refuses a node that needs the realtime executor in a lockstep graph, with exit 3 and
// the node's location, as run does; the executor chosen on the command line counts for both.
TEST(Cli, ARealtimeOnlyNodeInALockstepGraphIsAnInvalidGraph) {
  const fs::path dir = temp_dir("executor");
  std::string out;
  const fs::path graph = write_graph(dir, R"(nodes:
  - {id: src, type: counter_source, params: {rate_hz: 20, count: 3}}
  - {id: device, type: realtime_only}
connections:
  - {from: src.out, to: device.in}
)");
  EXPECT_EQ(run_cli({"validate", graph.string()}, &out), 3);
  EXPECT_THAT(out, HasSubstr("graph.yaml:4:24: error: node 'device' (realtime_only) needs the realtime executor"));
  EXPECT_EQ(run_cli({"run", graph.string()}, &out), 3);
  EXPECT_THAT(out, HasSubstr("the graph was not run"));
  EXPECT_EQ(run_cli({"validate", graph.string(), "--executor", "realtime"}, &out), 0) << out;
  EXPECT_EQ(run_cli({"run", graph.string(), "--executor", "realtime", "--no-progress"}, &out), 0) << out;
}

// sweep and ab check the graph before any run, and exit as `run` and `validate` do.
TEST(Cli, SweepAndAbExitAsRunDoesOnAnInvalidGraph) {
  const fs::path dir = temp_dir("experiment-codes");
  const fs::path bad = write_graph(temp_dir("experiment-bad"), "nodes:\n  - {id: a, type: relai}\n");
  const fs::path good = write_graph(dir, kCountToThree);
  const std::string missing = (dir / "missing.yaml").string();
  std::string out;
  auto report = [&](const std::string& name) { return (dir / name).string(); };
  EXPECT_EQ(run_cli({"sweep", missing, "--param", "src.count=1:2:1", "--report", report("s1")}, &out), 3) << out;
  EXPECT_THAT(out, HasSubstr("missing.yaml: error: no such graph file"));
  EXPECT_EQ(run_cli({"sweep", bad.string(), "--param", "src.count=1:2:1", "--report", report("s2")}, &out), 3) << out;
  EXPECT_THAT(out, HasSubstr("unknown node type 'relai'"));
  EXPECT_EQ(run_cli({"sweep", good.string(), "--param", "src.cout=1:2:1", "--report", report("s3")}, &out), 3) << out;
  EXPECT_THAT(out, HasSubstr("did you mean 'count'?"));
  EXPECT_EQ(
      run_cli({"sweep", good.string(), "--param", "src.count=1:2:1", "--set", "sink.kep=1", "--report", report("s4")}),
      3);
  // A value out of range at the end of the grid (rate_hz is at most 1e6) fails before any run too.
  EXPECT_EQ(
      run_cli({"sweep", good.string(), "--param", "src.rate_hz=1:2000000:1000000", "--report", report("s7")}, &out), 3)
      << out;
  EXPECT_EQ(run_cli({"ab", bad.string(), good.string(), "--seeds", "2", "--report", report("a1")}, &out), 3) << out;
  EXPECT_EQ(run_cli({"ab", good.string(), missing, "--seeds", "2", "--report", report("a2")}), 3);
  EXPECT_EQ(
      run_cli({"ab", good.string(), good.string(), "--set-b", "src.cout=1", "--seeds", "2", "--report", report("a3")}),
      3);
  // Nothing was run.
  for (const char* name : {"s1", "s2", "s3", "s4", "s7", "a1", "a2", "a3"})
    EXPECT_FALSE(fs::exists(dir / name / "runs")) << name;
  // The command line itself: still 2.
  EXPECT_EQ(run_cli({"sweep", good.string(), "--param", "src.count=2:1:1", "--report", report("s5")}), 2);
  EXPECT_EQ(run_cli({"sweep", good.string(), "--param", "src.count", "--report", report("s6")}), 2);
  EXPECT_EQ(run_cli({"ab", good.string(), good.string(), "--seeds", "1", "--report", report("a4")}), 2);
}

TEST(Cli, InspectPluginsAndDotDescribeTheGraph) {
  const fs::path dir = temp_dir("inspect");
  ::setenv("KESTREL_PLUGIN_PATH", KESTREL_TEST_PLUGIN_DIR, 1);
  std::string out;
  EXPECT_EQ(run_cli({"inspect", "scale"}, &out), 0);
  EXPECT_THAT(out, HasSubstr("Node type scale"));
  EXPECT_THAT(out, HasSubstr("factor"));
  EXPECT_THAT(out, HasSubstr("range [-1000000, 1000000]"));
  EXPECT_THAT(out, HasSubstr("one of {multiply, divide}"));
  EXPECT_EQ(run_cli({"inspect", "window"}, &out), 0);
  EXPECT_THAT(out, HasSubstr("Rules:\n    low <= high"));
  EXPECT_THAT(out, HasSubstr("fallback               float list             default [0, 0]  2 values"));
  // A message type by its full name or by its last part.
  EXPECT_EQ(run_cli({"inspect", "test.Number"}, &out), 0);
  EXPECT_THAT(out, HasSubstr("Message type test.Number"));
  EXPECT_EQ(run_cli({"inspect", "Number"}, &out), 0);
  EXPECT_THAT(out, HasSubstr("Message type test.Number"));
  // Its fields with type, unit and frame; a type that declares none says so.
  EXPECT_THAT(out, HasSubstr("    field  type    unit  frame\n"
                             "    index  int64   -     -\n"
                             "      publication index at the source\n"
                             "    value  double  m     world\n"));
  EXPECT_EQ(run_cli({"inspect", "Blob"}, &out), 0);
  EXPECT_THAT(out, HasSubstr("fields: not declared"));
  EXPECT_EQ(run_cli({"plugins"}, &out), 0);
  EXPECT_THAT(out, HasSubstr("counter_source"));
  EXPECT_THAT(out, HasSubstr("Publishes 0, 1, 2"));
  ::unsetenv("KESTREL_PLUGIN_PATH");

  const fs::path graph = write_graph(dir, R"(nodes:
  - {id: src, type: counter_source}
  - {id: sink, type: collector}
connections:
  - {from: src.out, to: sink.in}
)");
  EXPECT_EQ(run_cli({"dot", graph.string()}, &out), 0);
  EXPECT_THAT(out, HasSubstr("\"src\":out_out -> \"sink\":in_in"));
}

// A part: inspect prints its interface; a graph that connects past its ports is invalid (exit 3,
// at the connection, naming the ports); one that includes it twice validates.
TEST(Cli, APartIsInspectedAndReachedOnlyThroughItsPorts) {
  const fs::path dir = temp_dir("part");
  ::setenv("KESTREL_PLUGIN_PATH", KESTREL_TEST_PLUGIN_DIR, 1);
  fs::create_directories(dir / "parts");
  std::ofstream(dir / "parts" / "scaler.yaml") << R"(part: scaler
description: multiplies each number by a factor
inputs: {numbers: scale.in}
outputs: {scaled: scale.out}
args:
  factor: {default: 2.0, unit: x, description: the gain, to: scale.factor}
nodes:
  - {id: scale, type: scale}
)";
  std::string out;
  EXPECT_EQ(run_cli({"inspect", (dir / "parts" / "scaler.yaml").string()}, &out), 0);
  EXPECT_THAT(out, HasSubstr("Part scaler ("));
  EXPECT_THAT(out, HasSubstr("    numbers                test.Number                scale.in\n"));
  EXPECT_THAT(out,
              HasSubstr("    factor                 default 2.0 x              sets scale.factor\n      the gain"));
  const fs::path into = write_graph(dir, R"(include:
  - {part: parts/scaler.yaml, as: front}
nodes:
  - {id: src, type: counter_source}
connections:
  - {from: src.out, to: front/scale.in}
)");
  EXPECT_EQ(run_cli({"validate", into.string()}, &out), 3);
  EXPECT_THAT(out, HasSubstr("graph.yaml:7:25: error: 'front/scale' is inside part 'front'"));
  EXPECT_THAT(out, HasSubstr("through its ports (inputs: numbers; outputs: scaled)"));
  EXPECT_EQ(run_cli({"inspect", into.string()}, &out), 2);
  EXPECT_THAT(out, HasSubstr("is a runnable graph, not a part"));
  const fs::path twice = write_graph(dir, R"(include:
  - {part: parts/scaler.yaml, as: a}
  - {part: parts/scaler.yaml, as: b, args: {factor: 3.0}}
nodes:
  - {id: src, type: counter_source, params: {count: 3}}
  - {id: sink_a, type: collector}
  - {id: sink_b, type: collector}
connections:
  - {from: src.out, to: a.numbers}
  - {from: src.out, to: b.numbers}
  - {from: a.scaled, to: sink_a.in}
  - {from: b.scaled, to: sink_b.in}
)");
  EXPECT_EQ(run_cli({"validate", twice.string()}, &out), 0);
  EXPECT_EQ(run_cli({"dot", twice.string()}, &out), 0);  // each part a cluster named by its namespace
  EXPECT_THAT(out, HasSubstr("subgraph \"cluster_b\" {\n    label=\"b\";"));
  EXPECT_THAT(out, HasSubstr("\"src\":out_out -> \"b/scale\":in_in"));
  EXPECT_EQ(run_cli({"run", twice.string(), "--set", "b/scale.factor=5", "--no-progress"}, &out), 0);
  ::unsetenv("KESTREL_PLUGIN_PATH");
}

TEST(Cli, MotComputesClearMotOnMotChallengeFiles) {
  const fs::path dir = temp_dir("mot");
  // Two objects, three frames. The tracker adds a false positive (frame 1), misses object 2
  // (frame 2), and follows object 2 with a new identity (frame 3): an ID switch.
  std::ofstream(dir / "gt.txt") << "1,1,0,0,10,10,1,0,0,5\n1,2,100,0,10,10,1,2,0,5\n"
                                   "2,1,0,0,10,10,1,0,0,5\n2,2,100,0,10,10,1,2,0,5\n"
                                   "3,1,0,0,10,10,1,0,0,5\n3,2,100,0,10,10,1,2,0,5\n"
                                   "3,9,50,50,10,10,0,9,9,9\n";  // conf 0: ignored
  std::ofstream(dir / "test.txt") << "1,1,0,0,10,10,1,0,0,5\n1,2,100,0,10,10,1,2,0,5\n1,3,300,300,10,10,1,30,30,5\n"
                                     "2,1,0,0,10,10,1,0,0,5\n"
                                     "3,1,0,0,10,10,1,0,0,5\n3,3,100,0,10,10,1,2,0,5\n";
  for (const std::vector<std::string>& mode :
       {std::vector<std::string>{"--iou", "0.5"}, std::vector<std::string>{"--dist", "0.5"}}) {
    std::vector<std::string> args = {"mot", (dir / "gt.txt").string(), (dir / "test.txt").string(), "--json",
                                     (dir / "m.json").string()};
    args.insert(args.end(), mode.begin(), mode.end());
    std::string out;
    ASSERT_EQ(run_cli(args, &out), 0) << out;
    const auto m = nlohmann::json::parse(read_file(dir / "m.json"));
    EXPECT_DOUBLE_EQ(m.at("mota").get<double>(), 0.5) << mode[0];
    EXPECT_EQ(m.at("fp"), 1);
    EXPECT_EQ(m.at("fn"), 1);
    EXPECT_EQ(m.at("idsw"), 1);
    EXPECT_EQ(m.at("frag"), 1);
    EXPECT_EQ(m.at("num_objects"), 6);
    EXPECT_NEAR(m.at("idf1").get<double>(), 8.0 / 12.0, 1e-12);
    EXPECT_NEAR(m.at("motp").get<double>(), 0.0, 1e-12);
    // The mot_evaluator's names for the same figures (report.json's "tracking" section).
    EXPECT_EQ(m.at("fragmentations"), 1);
    EXPECT_EQ(m.at("mostly_tracked"), 1);
    EXPECT_EQ(m.at("partially_tracked"), 1);
    EXPECT_EQ(m.at("mostly_lost"), 0);
    EXPECT_EQ(m.at("frames"), 3);
    EXPECT_EQ(m.contains("motp_m"), mode[0] == "--dist");  // MOTP is in metres only between points
    EXPECT_EQ(m.at("metrics_meta").at("mota").at("higher_is_better"), true);
    // The names kestrel mot used before, kept for a release.
    EXPECT_EQ(m.at("mt"), 1);
    EXPECT_EQ(m.at("pt"), 1);
    EXPECT_EQ(m.at("ml"), 0);
  }
  std::string out;
  EXPECT_EQ(run_cli({"mot", (dir / "missing.txt").string(), (dir / "test.txt").string()}, &out), 2);
  EXPECT_THAT(out, HasSubstr("cannot open"));
}

TEST(Cli, MotRefusesRowsItCannotScore) {
  const fs::path dir = temp_dir("mot-bad");
  std::ofstream(dir / "good.txt") << "1,1,0,0,10,10\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"1,-1,0,0,10,10,2.3,-1,-1,-1\n", "bad.txt:1: the id must be a whole number >= 0, not -1"},
      {"1,1,0,0,10,10\n2.5,1,0,0,10,10\n", "bad.txt:2: the frame must be a whole number, not 2.5"},
      {"1e300,1,0,0,10,10\n", "bad.txt:1: the frame must be a whole number"},
      // Read as conf 0, this ground-truth row used to be dropped without a word.
      {"1,1,0,0,10,10,yes\n", "bad.txt:1: conf, x, y and z must be numbers, not 'yes'"},
      {"1,1,0,0,10,10,1,0,0,5m\n", "bad.txt:1: conf, x, y and z must be numbers, not '5m'"},
  };
  for (const auto& [text, message] : cases) {
    std::ofstream(dir / "bad.txt") << text;
    std::string out;
    EXPECT_EQ(run_cli({"mot", (dir / "bad.txt").string(), (dir / "good.txt").string()}, &out), 2) << text;
    EXPECT_THAT(out, HasSubstr(message));
  }
}

// An output that cannot be written (a full device, a folder that cannot be made) is an error
// that names the file, with exit code 1, never a silent loss.
TEST(Cli, FailedWritesNameTheFileAndExitOne) {
  const fs::path dir = temp_dir("writes");
  std::ofstream(dir / "blocker") << "a file where a folder should be\n";
  fs::create_symlink("/dev/full", dir / "full.png");
  std::ofstream(dir / "gt.txt") << "1,1,0,0,10,10,1,0,0,5\n2,1,0,0,10,10,1,0,0,5\n";
  std::ofstream(dir / "table.csv") << "x,y\n1,2\n2,3\n";
  std::string out;
  const std::string gt = (dir / "gt.txt").string(), csv = (dir / "table.csv").string();

  EXPECT_EQ(run_cli({"mot", gt, gt, "--json", "/dev/full"}, &out), 1) << out;
  EXPECT_THAT(out, HasSubstr("cannot write /dev/full"));
  EXPECT_EQ(run_cli({"mot", gt, gt, "--json", (dir / "blocker" / "m.json").string()}, &out), 1) << out;
  EXPECT_THAT(out, HasSubstr("blocker/m.json"));

  EXPECT_EQ(run_cli({"plot", csv, "--x", "x", "--y", "y", "-o", "/dev/full"}, &out), 1) << out;
  EXPECT_THAT(out, HasSubstr("/dev/full"));
  EXPECT_EQ(run_cli({"plot", csv, "--x", "x", "--y", "y", "-o", (dir / "full.png").string()}, &out), 1) << out;
  EXPECT_THAT(out, HasSubstr("full.png"));
  EXPECT_EQ(run_cli({"plot", csv, "--x", "x", "--y", "y", "-o", (dir / "blocker" / "p.png").string()}, &out), 1);
  EXPECT_THAT(out, HasSubstr("blocker/p.png"));

  const fs::path graph = write_graph(dir, kCountToThree);
  EXPECT_EQ(run_cli({"dot", graph.string(), "-o", "/dev/full"}, &out), 1) << out;
  EXPECT_THAT(out, HasSubstr("cannot write /dev/full"));

  // A report folder that cannot be made: nothing is run.
  EXPECT_EQ(
      run_cli({"sweep", graph.string(), "--param", "src.count=1:2:1", "--report", (dir / "blocker" / "sweep").string()},
              &out),
      1)
      << out;
  EXPECT_THAT(out, HasSubstr("blocker/sweep"));
  // Summaries written to a full device.
  fs::create_directories(dir / "sweep");
  fs::create_symlink("/dev/full", dir / "sweep" / "sweep.csv");
  EXPECT_EQ(
      run_cli({"sweep", graph.string(), "--param", "src.count=1:2:1", "--report", (dir / "sweep").string()}, &out), 1)
      << out;
  EXPECT_THAT(out, HasSubstr("sweep.csv"));
  fs::create_directories(dir / "ab");
  fs::create_symlink("/dev/full", dir / "ab" / "ab.json");
  EXPECT_EQ(run_cli({"ab", graph.string(), graph.string(), "--seeds", "2", "--report", (dir / "ab").string()}, &out), 1)
      << out;
  EXPECT_THAT(out, HasSubstr("ab.json"));
}

// kestrel plot takes units from metrics_meta.json beside the CSV (as kestrel sweep leaves it), or
// from --meta; a --meta file without metrics_meta is an input error.
TEST(Cli, PlotReadsMetricsMeta) {
  const fs::path dir = temp_dir("plot-meta");
  std::ofstream(dir / "sweep.csv") << "a.x,tracking.lag_s,tracking.mota\n1,-0.2,0.9\n2,0.1,0.95\n";
  std::ofstream(dir / "metrics_meta.json")
      << R"({"metrics_meta": {"tracking.lag_s": {"unit": "s", "higher_is_better": false, "by_magnitude": true}}})";
  std::ofstream(dir / "plain.json") << R"({"tracking": {"mota": 1}})";
  const std::string csv = (dir / "sweep.csv").string();
  std::string out;
  EXPECT_EQ(
      run_cli({"plot", csv, "--x", "a.x", "--y", "tracking.lag_s,tracking.mota", "-o", (dir / "a.png").string()}, &out),
      0)
      << out;
  EXPECT_TRUE(fs::exists(dir / "a.png"));
  // An undefined value (an empty cell, as sweep.csv writes a null metric) is a gap, and counted.
  std::ofstream(dir / "gaps.csv") << "a.x,tracking.mota\n1,0.9\n2,\n3,0.95\n";
  EXPECT_EQ(run_cli({"plot", (dir / "gaps.csv").string(), "--x", "a.x", "--y", "tracking.mota", "-o",
                     (dir / "gaps.png").string()},
                    &out),
            0)
      << out;
  EXPECT_THAT(out, HasSubstr("tracking.mota: 1 of 3 rows undefined (empty cells), drawn as gaps"));
  EXPECT_EQ(run_cli({"plot", csv, "--x", "a.x", "--y", "tracking.mota", "-o", (dir / "b.png").string(), "--meta",
                     (dir / "plain.json").string()},
                    &out),
            2);
  EXPECT_THAT(out, HasSubstr("plain.json: expected a JSON object with \"metrics_meta\""));
  EXPECT_EQ(run_cli({"plot", csv, "--x", "a.x", "--y", "tracking.mota", "-o", (dir / "c.png").string(), "--meta",
                     (dir / "missing.json").string()},
                    &out),
            2);
}

// --live PORT serves this machine only; ADDRESS:PORT opens the view elsewhere, with a warning.
TEST(Cli, LiveListensOnThisMachineUnlessAnAddressIsGiven) {
  using kestrel::cli::parse_live_endpoint;
  ASSERT_TRUE(parse_live_endpoint("8765"));
  EXPECT_EQ(parse_live_endpoint("8765")->address, "127.0.0.1");
  EXPECT_EQ(parse_live_endpoint("8765")->port, 8765);
  EXPECT_EQ(parse_live_endpoint("0.0.0.0:9000")->address, "0.0.0.0");
  EXPECT_EQ(parse_live_endpoint("0.0.0.0:9000")->port, 9000);
  EXPECT_EQ(parse_live_endpoint("[::1]:0")->address, "::1");
  for (const char* bad : {"", "abc", "65536", "-1", ":8765", "host:", "host:80x", "8765 "})
    EXPECT_FALSE(parse_live_endpoint(bad)) << bad;

  const fs::path dir = temp_dir("live");
  const fs::path graph = write_graph(dir, kCountToThree);
  std::string out;
  EXPECT_EQ(run_cli({"run", graph.string(), "--no-progress", "--live", "0"}, &out), 0);
  EXPECT_THAT(out, HasSubstr("live view: foxglove.websocket.v1 on ws://127.0.0.1:"));
  EXPECT_THAT(out, Not(HasSubstr("open to the network")));
  EXPECT_EQ(run_cli({"run", graph.string(), "--no-progress", "--live", "0.0.0.0:0"}, &out), 0);
  EXPECT_THAT(out, HasSubstr("ws://0.0.0.0:"));
  EXPECT_THAT(out, HasSubstr("open to the network without authentication"));
  EXPECT_EQ(run_cli({"run", graph.string(), "--live", "eighty"}, &out), 2);
  EXPECT_THAT(out, HasSubstr("--live takes PORT or ADDRESS:PORT (0 to 65535), not 'eighty'"));
}
