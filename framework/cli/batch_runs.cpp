#include "batch_runs.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <map>

#include "kestrel/error.hpp"
#include "report_metrics.hpp"

extern char** environ;

namespace kestrel::cli {

namespace {

std::string self_path() {
  std::error_code ec;
  const auto p = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) throw Error("cannot find the kestrel executable: " + ec.message());
  return p.string();
}

pid_t spawn(const std::string& exe, const BatchJob& job) {
  std::filesystem::create_directories(job.report_dir);
  std::vector<std::string> argv_strings = {exe};
  argv_strings.insert(argv_strings.end(), job.args.begin(), job.args.end());
  std::vector<char*> argv;
  for (auto& s : argv_strings) argv.push_back(s.data());
  argv.push_back(nullptr);
  const std::string log = (job.report_dir / "run.log").string();
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  pid_t pid = -1;
  const int rc = posix_spawn(&pid, exe.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) throw Error("cannot start a run: " + std::string(std::strerror(rc)));
  return pid;
}

}  // namespace

std::vector<BatchResult> run_batch(const std::vector<BatchJob>& jobs, int parallel) {
  const std::string exe = self_path();
  std::vector<BatchResult> results(jobs.size());
  std::map<pid_t, std::size_t> running;
  std::size_t next = 0, done = 0;
  while (done < jobs.size()) {
    while (next < jobs.size() && static_cast<int>(running.size()) < std::max(1, parallel)) {
      running[spawn(exe, jobs[next])] = next;
      ++next;
    }
    int status = 0;
    const pid_t pid = waitpid(-1, &status, 0);
    if (pid < 0) throw Error("lost track of a run");
    const auto it = running.find(pid);
    if (it == running.end()) continue;
    const std::size_t index = it->second;
    running.erase(it);
    ++done;
    BatchResult& r = results[index];
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    r.report = read_report(jobs[index].report_dir);
    std::fprintf(stderr, "\r[kestrel] %zu/%zu runs done", done, jobs.size());
  }
  std::fprintf(stderr, "\n");
  return results;
}

}  // namespace kestrel::cli
