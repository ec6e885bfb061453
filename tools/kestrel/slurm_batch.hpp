#pragma once
// The runs of `kestrel sweep` and `kestrel ab` as a Slurm job array (docs/cluster.md). One run is
// one task: `kestrel batch-task DIR I` runs job I of DIR/batch/tasks.json, its output in the run's
// run.log and its exit code in the run's exit_code file. A second job, after the array whatever
// became of it (`--dependency=afterany`), runs `kestrel collect DIR`, which summarises as a local
// run would. A task that left no exit code (killed at its time limit, cancelled, its node lost) is
// reported with the state Slurm gives it, and counted as failed.
//
//   DIR/batch/command.json  the subcommand and its arguments (paths absolute), to plan again
//   DIR/batch/tasks.json    per task: its `kestrel run` arguments and report folder
//   DIR/batch/slurm.json    the array's and the collector's job ids
//   DIR/batch/slurm-A_I.out Slurm's own output of task I (the run's is in its run.log)
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "batch_runs.hpp"
#include "commands.hpp"

namespace kestrel::cli {

struct SlurmJobs {
  std::string array;    ///< the array job's id
  std::string collect;  ///< the collector's id
};

/// Writes DIR/batch/ and submits the array and its collector. On SIGINT or SIGTERM before both
/// are accepted, cancels what was submitted and throws Interrupted. Throws CommandError when
/// sbatch is missing or refuses.
SlurmJobs submit_to_slurm(const std::filesystem::path& dir, const nlohmann::json& command,
                          const std::vector<BatchJob>& jobs, const BatchBackend& backend);

/// Waits until both jobs have left the queue, showing how many tasks are done; on SIGINT or
/// SIGTERM cancels them and throws Interrupted.
void wait_for_slurm(const std::filesystem::path& dir, const SlurmJobs& jobs, std::size_t tasks);

/// What the tasks of DIR left: each job's exit code and report, and for a task without an exit
/// code, its Slurm state (sacct, else scontrol) in `failure`.
std::vector<BatchResult> collect_slurm_results(const std::filesystem::path& dir, const std::vector<BatchJob>& jobs);

/// `kestrel batch-task DIR I`: runs task I of DIR/batch/tasks.json; returns the run's exit code.
int run_batch_task(const std::filesystem::path& dir, std::size_t index);

/// DIR/batch/command.json, as submit_to_slurm wrote it. Throws CommandError(kUsage) when DIR holds
/// no submitted batch.
nlohmann::json read_batch_command(const std::filesystem::path& dir);

}  // namespace kestrel::cli
