#include "slurm_batch.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <thread>

#include "blocked_signals.hpp"
#include "command_errors.hpp"
#include "output_files.hpp"
#include "report_metrics.hpp"

namespace kestrel::cli {

namespace {

std::filesystem::path batch_dir(const std::filesystem::path& dir) { return dir / "batch"; }

struct ToolOutput {
  int exit_code = -1;
  std::string out;  ///< standard output and error together
};

// Runs a Slurm command (no shell: arguments pass as they are) and captures what it prints.
ToolOutput run_tool(const std::vector<std::string>& argv) {
  int pipe_fds[2];
  if (pipe2(pipe_fds, O_CLOEXEC) != 0) throw Error(std::string("pipe: ") + std::strerror(errno));
  std::vector<std::string> args = argv;
  std::vector<char*> c_args;
  for (auto& a : args) c_args.push_back(a.data());
  c_args.push_back(nullptr);
  const pid_t pid = fork();
  if (pid < 0) throw Error(std::string("fork: ") + std::strerror(errno));
  if (pid == 0) {
    dup2(pipe_fds[1], STDOUT_FILENO);
    dup2(pipe_fds[1], STDERR_FILENO);
    sigset_t none;
    sigemptyset(&none);
    pthread_sigmask(SIG_SETMASK, &none, nullptr);
    execvp(c_args[0], c_args.data());
    _exit(127);
  }
  close(pipe_fds[1]);
  ToolOutput result;
  char chunk[4096];
  for (ssize_t n; (n = read(pipe_fds[0], chunk, sizeof chunk)) != 0;) {
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) break;
    result.out.append(chunk, static_cast<std::size_t>(n));
  }
  close(pipe_fds[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return result;
}

std::string trimmed(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ' || s.back() == '\r')) s.pop_back();
  return s;
}

// sbatch --parsable prints "JOBID" or "JOBID;CLUSTER".
std::string submit(const std::vector<std::string>& argv) {
  const ToolOutput r = run_tool(argv);
  if (r.exit_code == 127)
    throw CommandError(kRunFailed, "sbatch not found: install Slurm's client (scripts/install-deps installs it)");
  if (r.exit_code != 0) throw CommandError(kRunFailed, "sbatch refused the job: " + trimmed(r.out));
  std::string id = trimmed(r.out);
  if (const auto at = id.rfind('\n'); at != std::string::npos) id = id.substr(at + 1);  // after any warning
  if (const auto semicolon = id.find(';'); semicolon != std::string::npos) id.resize(semicolon);
  if (id.empty() || id.find_first_not_of("0123456789") != std::string::npos)
    throw CommandError(kRunFailed, "sbatch gave no job id: " + trimmed(r.out));
  return id;
}

void cancel(const std::vector<std::string>& job_ids) {
  std::vector<std::string> argv = {"scancel"};
  argv.insert(argv.end(), job_ids.begin(), job_ids.end());
  if (job_ids.size() > 0) run_tool(argv);
}

// A signal received since the last look, without waiting (SIGINT and SIGTERM are blocked).
int pending_signal(const sigset_t& set) {
  const timespec now{0, 0};
  const int sig = sigtimedwait(&set, nullptr, &now);
  return sig > 0 ? sig : 0;
}

nlohmann::json read_json(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw CommandError(kUsage, "cannot read " + file.string());
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw CommandError(kRunFailed, file.string() + ": " + e.what());
  }
}

// The state Slurm gives task `task` of array `array`: sacct where accounting runs, else scontrol
// (which knows a job for MinJobAge after it ends); empty when neither knows it.
std::string slurm_state(const std::string& array, std::size_t task) {
  const std::string id = array + "_" + std::to_string(task);
  const ToolOutput acct = run_tool({"sacct", "-n", "-P", "-X", "-j", id, "-o", "State"});
  if (acct.exit_code == 0) {
    std::string state = trimmed(acct.out);
    if (const auto space = state.find(' '); space != std::string::npos) state.resize(space);  // "CANCELLED by 0"
    if (!state.empty() && state.find('\n') == std::string::npos) return state;
  }
  const ToolOutput show = run_tool({"scontrol", "show", "job", id});
  if (show.exit_code == 0) {
    const auto at = show.out.find("JobState=");
    if (at != std::string::npos) {
      const auto end = show.out.find_first_of(" \n", at);
      return show.out.substr(at + 9, end == std::string::npos ? std::string::npos : end - at - 9);
    }
  }
  return "";
}

}  // namespace

SlurmJobs submit_to_slurm(const std::filesystem::path& dir, const nlohmann::json& command,
                          const std::vector<BatchJob>& jobs, const BatchBackend& backend) {
  if (jobs.empty()) throw CommandError(kUsage, "nothing to submit");
  const std::filesystem::path batch = batch_dir(dir);
  make_folder(batch);
  nlohmann::json tasks = nlohmann::json::array();
  for (const BatchJob& j : jobs) tasks.push_back({{"args", j.args}, {"report_dir", j.report_dir.string()}});
  write_file(batch / "command.json", command.dump(1) + "\n");
  write_file(batch / "tasks.json", tasks.dump(1) + "\n");
  const std::string exe = kestrel_executable();
  // Tasks run where the command was run, as local runs do: relative paths in --set mean the same.
  const std::string workdir = std::filesystem::current_path().string();

  std::vector<std::string> common;
  if (!backend.partition.empty()) common.push_back("--partition=" + backend.partition);
  common.insert(common.end(), backend.sbatch_args.begin(), backend.sbatch_args.end());
  std::vector<std::string> array_argv = {"sbatch",
                                         "--parsable",
                                         "--job-name=kestrel-" + command.at("command").get<std::string>(),
                                         "--array=0-" + std::to_string(jobs.size() - 1) +
                                             (backend.array_limit > 0 ? "%" + std::to_string(backend.array_limit) : ""),
                                         "--output=" + (batch / "slurm-%A_%a.out").string(),
                                         "--chdir=" + workdir};
  if (!backend.time.empty()) array_argv.push_back("--time=" + backend.time);
  array_argv.insert(array_argv.end(), common.begin(), common.end());
  array_argv.push_back("--wrap=exec '" + exe + "' batch-task '" + dir.string() + "' \"$SLURM_ARRAY_TASK_ID\"");

  // Until both are accepted, a Ctrl-C cancels what was submitted: no orphan array.
  const BlockedSignals blocked{SIGINT, SIGTERM};
  SlurmJobs ids;
  ids.array = submit(array_argv);
  if (const int sig = pending_signal(blocked.set())) {
    cancel({ids.array});
    throw Interrupted(sig, "interrupted while submitting: job " + ids.array + " cancelled");
  }
  std::vector<std::string> collect_argv = {"sbatch",
                                           "--parsable",
                                           "--job-name=kestrel-collect",
                                           "--dependency=afterany:" + ids.array,
                                           "--output=" + (batch / "collect.out").string(),
                                           "--chdir=" + workdir};
  collect_argv.insert(collect_argv.end(), common.begin(), common.end());
  collect_argv.push_back("--wrap=exec '" + exe + "' collect '" + dir.string() + "'");
  try {
    ids.collect = submit(collect_argv);
  } catch (...) {
    cancel({ids.array});
    throw;
  }
  if (const int sig = pending_signal(blocked.set())) {
    cancel({ids.array, ids.collect});
    throw Interrupted(sig, "interrupted while submitting: jobs " + ids.array + " and " + ids.collect + " cancelled");
  }
  write_file(
      batch / "slurm.json",
      nlohmann::json{{"array_job", ids.array}, {"collect_job", ids.collect}, {"tasks", jobs.size()}}.dump(1) + "\n");
  return ids;
}

void wait_for_slurm(const std::filesystem::path& dir, const SlurmJobs& ids, std::size_t tasks) {
  const BlockedSignals blocked{SIGINT, SIGTERM};
  std::size_t last_done = static_cast<std::size_t>(-1);
  for (;;) {
    if (const int sig = pending_signal(blocked.set())) {
      cancel({ids.array, ids.collect});
      throw Interrupted(sig, "interrupted: jobs " + ids.array + " and " + ids.collect +
                                 " cancelled (`kestrel collect " + dir.string() + "` summarises what ended)");
    }
    const ToolOutput q = run_tool({"squeue", "-h", "-r", "-j", ids.array + "," + ids.collect, "-o", "%i"});
    std::size_t queued_tasks = 0;
    bool collector_queued = false;
    std::istringstream lines(q.out);
    for (std::string line; std::getline(lines, line);) {
      line = trimmed(line);
      if (line == ids.collect)
        collector_queued = true;
      else if (line.rfind(ids.array, 0) == 0)
        ++queued_tasks;
    }
    // squeue fails once a job it is asked for has left the queue on some versions: then only the
    // files tell.
    if (q.exit_code != 0) collector_queued = !std::filesystem::exists(batch_dir(dir) / "collected");
    const std::size_t done = tasks - std::min(tasks, queued_tasks);
    if (done != last_done) {
      std::fprintf(stderr, "\r[kestrel] slurm: %zu/%zu tasks done", done, tasks);
      last_done = done;
    }
    if (!collector_queued && queued_tasks == 0) break;
    std::this_thread::sleep_for(std::chrono::seconds(2));
  }
  std::fprintf(stderr, "\n");
}

std::vector<BatchResult> collect_slurm_results(const std::filesystem::path& dir, const std::vector<BatchJob>& jobs) {
  std::string array;
  if (const auto slurm = batch_dir(dir) / "slurm.json"; std::filesystem::exists(slurm))
    array = read_json(slurm).value("array_job", "");
  std::vector<BatchResult> results(jobs.size());
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    BatchResult& r = results[i];
    r.report = read_report(jobs[i].report_dir);
    std::ifstream code(jobs[i].report_dir / "exit_code");
    const bool ended = static_cast<bool>(code >> r.exit_code);
    if (ended && r.exit_code == 0) continue;
    // A run that failed, or a task that never ran to its end: what Slurm says of it.
    const std::string task =
        "runs/" + jobs[i].report_dir.filename().string() + ", Slurm task " + array + "_" + std::to_string(i);
    const std::string state = array.empty() ? "" : slurm_state(array, i);
    if (ended) {
      r.failure = task + ": " + (state.empty() ? "" : state + ", ") + "the run exited " + std::to_string(r.exit_code) +
                  " (its run.log says why)";
      continue;
    }
    r.exit_code = kRunFailed;
    if (!state.empty())
      r.failure = task + ": " + state + ", no exit code";
    else if (!std::filesystem::exists(jobs[i].report_dir / "run.log"))
      r.failure = task +
                  ": never ran, and Slurm keeps no record of it (a pending task cancelled leaves none where "
                  "the cluster keeps no accounting)";
    else
      r.failure = task + ": stopped before its end, and Slurm keeps no record of it";
  }
  return results;
}

int run_batch_task(const std::filesystem::path& dir, std::size_t index) {
  const nlohmann::json tasks = read_json(batch_dir(dir) / "tasks.json");
  if (index >= tasks.size())
    throw CommandError(kUsage, "task " + std::to_string(index) + " of " + std::to_string(tasks.size()));
  BatchJob job;
  job.args = tasks[index].at("args").get<std::vector<std::string>>();
  job.report_dir = tasks[index].at("report_dir").get<std::string>();
  std::filesystem::remove(job.report_dir / "exit_code");  // a task run again starts clean
  const std::vector<BatchResult> r = run_batch({job}, 1);
  write_file(job.report_dir / "exit_code", std::to_string(r.front().exit_code) + "\n");
  return r.front().exit_code;
}

nlohmann::json read_batch_command(const std::filesystem::path& dir) {
  const auto file = batch_dir(dir) / "command.json";
  if (!std::filesystem::exists(file))
    throw CommandError(kUsage, dir.string() + " holds no submitted batch (no batch/command.json)");
  return read_json(file);
}

}  // namespace kestrel::cli
