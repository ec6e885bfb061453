#pragma once
// Runs many `kestrel run` jobs as child processes, a few at a time, and reads back their
// report.json files. Shared by `kestrel sweep` and `kestrel ab`.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace kestrel::cli {

struct BatchJob {
  std::vector<std::string> args;  ///< after "kestrel": run GRAPH --set ... --report DIR ...
  std::filesystem::path report_dir;
};

struct BatchResult {
  int exit_code = 0;
  nlohmann::json report;  ///< empty if the run wrote none
};

/// Runs the jobs with at most `parallel` at once; each job's output goes to report_dir/run.log.
std::vector<BatchResult> run_batch(const std::vector<BatchJob>& jobs, int parallel);

}  // namespace kestrel::cli
