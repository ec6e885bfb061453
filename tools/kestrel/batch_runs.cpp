#include "batch_runs.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <map>

#include "blocked_signals.hpp"
#include "kestrel/error.hpp"
#include "output_files.hpp"
#include "report_metrics.hpp"

namespace kestrel::cli {

namespace {

using Clock = std::chrono::steady_clock;

// How long stopped runs get to drain and write their reports before they are killed.
constexpr auto kGrace = std::chrono::seconds(20);

// Each run gets its own process group, so that a Ctrl-C at the terminal reaches the batch only,
// which then stops each run once (a run signalled twice quits at once, without its report).
pid_t spawn(const std::string& exe, const BatchJob& job, const sigset_t& child_mask) {
  make_folder(job.report_dir);
  // Everything the child needs is made before fork: after it, only async-signal-safe calls.
  std::vector<std::string> argv_strings = {exe};
  argv_strings.insert(argv_strings.end(), job.args.begin(), job.args.end());
  std::vector<char*> argv;
  for (auto& s : argv_strings) argv.push_back(s.data());
  argv.push_back(nullptr);
  const std::filesystem::path log = job.report_dir / "run.log";
  const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw CommandError(kRunFailed, "cannot write " + log.string() + ": " + std::strerror(errno));
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) {
    const int error = errno;
    close(fd);
    throw Error("cannot start a run: " + std::string(std::strerror(error)));
  }
  if (pid == 0) {
    setpgid(0, 0);
    // A batch killed outright (SIGKILL) takes its runs along instead of leaving them running.
    prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (getppid() != parent) _exit(127);
    if (dup2(fd, STDOUT_FILENO) < 0 || dup2(fd, STDERR_FILENO) < 0) _exit(127);
    pthread_sigmask(SIG_SETMASK, &child_mask, nullptr);
    execv(exe.c_str(), argv.data());
    _exit(127);
  }
  close(fd);
  setpgid(pid, pid);  // from both sides: the group exists before either goes on
  return pid;
}

void signal_all(const std::map<pid_t, std::size_t>& running, int sig) {
  for (const auto& [pid, _] : running) kill(pid, sig);
}

const char* signal_name(int sig) { return sig == SIGINT ? "SIGINT" : sig == SIGTERM ? "SIGTERM" : "a signal"; }

}  // namespace

std::string kestrel_executable() {
  std::error_code ec;
  const auto p = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) throw Error("cannot find the kestrel executable: " + ec.message());
  return p.string();
}

std::vector<BatchResult> run_batch(const std::vector<BatchJob>& jobs, int parallel) {
  const std::string exe = kestrel_executable();
  const BlockedSignals blocked{SIGINT, SIGTERM, SIGCHLD};
  std::vector<BatchResult> results(jobs.size());
  std::map<pid_t, std::size_t> running;
  std::size_t next = 0, done = 0;
  int stop_signal = 0;  // the signal that stopped the batch, once one has
  bool killed = false;
  Clock::time_point kill_at;
  while (!running.empty() || (!stop_signal && next < jobs.size())) {
    while (!stop_signal && next < jobs.size() && static_cast<int>(running.size()) < std::max(1, parallel)) {
      try {
        running[spawn(exe, jobs[next], blocked.before())] = next;
      } catch (...) {
        // The batch cannot go on: its running runs must not outlive it.
        signal_all(running, SIGTERM);
        for (const auto& [pid, _] : running) waitpid(pid, nullptr, 0);
        throw;
      }
      ++next;
    }
    // Reap every run that has ended.
    int status = 0;
    for (pid_t pid; (pid = waitpid(-1, &status, WNOHANG)) > 0;) {
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
    if (running.empty()) continue;
    // Wait for a run to end or a signal; wake every second to enforce the grace period.
    const timespec second{1, 0};
    const int sig = sigtimedwait(&blocked.set(), nullptr, &second);
    if (sig == SIGINT || sig == SIGTERM) {
      if (!stop_signal) {
        stop_signal = sig;
        kill_at = Clock::now() + kGrace;
        std::fprintf(stderr, "\n[kestrel] %s: stopping %zu run(s) (signal again to kill them at once)\n",
                     signal_name(sig), running.size());
        signal_all(running, SIGTERM);
      } else if (!killed) {
        killed = true;
        signal_all(running, SIGKILL);
      }
    }
    if (stop_signal && !killed && Clock::now() >= kill_at) {
      killed = true;
      std::fprintf(stderr, "\n[kestrel] %zu run(s) still draining after %lld s: killing them\n", running.size(),
                   static_cast<long long>(kGrace.count()));
      signal_all(running, SIGKILL);
    }
  }
  std::fprintf(stderr, "\n");
  if (stop_signal)
    throw Interrupted(stop_signal, std::string("interrupted by ") + signal_name(stop_signal) + ": " +
                                       std::to_string(done) + " of " + std::to_string(jobs.size()) +
                                       " runs ended (the stopped ones with partial reports); nothing was summarised");
  return results;
}

}  // namespace kestrel::cli
