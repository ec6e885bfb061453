// The kestrel command line: exit codes, reports, and clean shutdown on SIGINT and SIGTERM.
#include <fcntl.h>
#include <gmock/gmock.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "test_support.hpp"

extern char** environ;

namespace fs = std::filesystem;
using ::testing::HasSubstr;

namespace {

fs::path temp_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("kestrel-cli-" + name + "-" + std::to_string(getpid()));
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

std::string read(const fs::path& f) {
  std::ifstream in(f);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// Waits until the process's output holds `line` (true), or the process has exited or the time is
// up (false). The process is not reaped: wait_exit() still gets its status.
bool wait_for_line(const Process& p, const std::string& line, std::chrono::seconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < deadline) {
    if (read(p.output).find(line) != std::string::npos) return true;
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
  if (output) *output = read(out);
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
    FAIL() << "the run never said it was running:\n" << read(p.output);
  }
  ASSERT_EQ(kill(p.pid, GetParam()), 0);
  EXPECT_EQ(wait_exit(p), 0) << read(p.output);
  const auto report = nlohmann::json::parse(read(dir / "report" / "report.json"));
  EXPECT_EQ(report.at("outcome"), "stopped");
  // The sink's finish() ran after the queues drained: it saw every message the source sent.
  std::uint64_t sent = 0;
  for (const auto& n : report.at("stats").at("nodes"))
    if (n.at("id") == "src") sent = n.at("messages_out");
  EXPECT_GT(sent, 0u);  // the source had ticked before the signal
  EXPECT_EQ(report.at("sink").at("count"), sent);
  EXPECT_THAT(read(p.output), HasSubstr("src.out -> slow.in"));  // --stats printed
  EXPECT_TRUE(fs::exists(dir / "report" / "report.md"));
}

INSTANTIATE_TEST_SUITE_P(Signals, CleanShutdown, ::testing::Values(SIGINT, SIGTERM));

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

TEST(Cli, InspectPluginsAndDotDescribeTheGraph) {
  const fs::path dir = temp_dir("inspect");
  ::setenv("KESTREL_PLUGIN_PATH", KESTREL_TEST_PLUGIN_DIR, 1);
  std::string out;
  EXPECT_EQ(run_cli({"inspect", "scale"}, &out), 0);
  EXPECT_THAT(out, HasSubstr("Node type scale"));
  EXPECT_THAT(out, HasSubstr("factor"));
  EXPECT_THAT(out, HasSubstr("range [-1000000, 1000000]"));
  EXPECT_THAT(out, HasSubstr("one of {multiply, divide}"));
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
    const auto m = nlohmann::json::parse(read(dir / "m.json"));
    EXPECT_DOUBLE_EQ(m.at("mota").get<double>(), 0.5) << mode[0];
    EXPECT_EQ(m.at("fp"), 1);
    EXPECT_EQ(m.at("fn"), 1);
    EXPECT_EQ(m.at("idsw"), 1);
    EXPECT_EQ(m.at("frag"), 1);
    EXPECT_EQ(m.at("num_objects"), 6);
    EXPECT_NEAR(m.at("idf1").get<double>(), 8.0 / 12.0, 1e-12);
    EXPECT_NEAR(m.at("motp").get<double>(), 0.0, 1e-12);
  }
  std::string out;
  EXPECT_EQ(run_cli({"mot", (dir / "missing.txt").string(), (dir / "test.txt").string()}, &out), 2);
  EXPECT_THAT(out, HasSubstr("cannot open"));
}
