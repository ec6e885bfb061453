#pragma once
// Runs many `kestrel run` jobs as child processes, a few at a time, and reads back their
// report.json files. Shared by `kestrel sweep` and `kestrel ab`.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "command_errors.hpp"

namespace kestrel::cli {

struct BatchJob {
  std::vector<std::string> args;  ///< after "kestrel": run GRAPH --set ... --report DIR ...
  std::filesystem::path report_dir;
};

struct BatchResult {
  int exit_code = 0;
  nlohmann::json report;  ///< null if the run wrote none
  std::string failure;    ///< why a run that left no exit code failed (a Slurm state), else empty
};

/// SIGINT or SIGTERM stopped the batch; its code is 128 + the signal, as a shell reports it.
class Interrupted : public CommandError {
 public:
  Interrupted(int signal, const std::string& message)
      : CommandError(static_cast<ExitCode>(128 + signal), message), signal_(signal) {}
  int signal() const { return signal_; }

 private:
  int signal_;
};

/// The path of the running kestrel executable, which every run of a batch is started as.
std::string kestrel_executable();

/// Runs the jobs with at most `parallel` at once; each job's output goes to report_dir/run.log.
/// On SIGINT or SIGTERM it starts no more runs, stops the running ones (each drains and writes
/// its report; a second signal, or 20 s, kills them), waits for them and throws Interrupted.
std::vector<BatchResult> run_batch(const std::vector<BatchJob>& jobs, int parallel);

}  // namespace kestrel::cli
