#pragma once
// Planning the runs of `kestrel sweep` and `kestrel ab`: which graph, with which overrides and
// seed, reporting to which folder. Nothing here starts a process.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "batch_runs.hpp"
#include "commands.hpp"

namespace kestrel::cli {

/// One swept parameter: node.param and its values, as they will be passed to --set.
struct SweptParam {
  std::string key;
  std::vector<std::string> values;
};

/// "node.param=start:stop:step", stop included.
SweptParam parse_range(const std::string& text);

/// The arguments of one `kestrel run`, after the program name.
std::vector<std::string> run_args(const std::string& graph, const std::vector<std::string>& sets, int seed,
                                  const std::optional<double>& duration, const std::filesystem::path& report_dir);

/// The points of a sweep and the runs of each. From --param, the points are a grid: every
/// combination of the swept values, each run with seeds 1..seeds. From --cases, they are the rows
/// of the file, each run once with the seed its row gives or, without a seed column, with seeds
/// 1..seeds. Job j runs point_of(j) with seed_of(j); the jobs of a point follow each other.
struct SweepPlan {
  /// The grid's ranges; for cases, the file's node.param columns, each with its value per case.
  std::vector<SweptParam> params;
  std::vector<std::vector<std::string>> grid;  ///< per point, one value per param ("": not set, in a case)
  int seeds = 1;                               ///< runs per point
  std::string cases_file;                      ///< the --cases file; empty for a grid
  std::vector<int> case_lines;                 ///< per case, its line in cases_file
  bool case_seeds = false;                     ///< each case runs once, with its row's seed
  std::vector<std::string> overrides;          ///< the fixed --set values
  std::vector<BatchJob> jobs;
  std::vector<std::size_t> job_points;  ///< per job, its point
  std::vector<int> job_seeds;           ///< per job, its seed

  bool from_cases() const { return !cases_file.empty(); }
  /// The --set values of a point: the fixed overrides, then its values (those that are set).
  std::vector<std::string> sets_for(std::size_t point) const;
  std::size_t point_of(std::size_t job) const { return job_points.at(job); }
  int seed_of(std::size_t job) const { return job_seeds.at(job); }
};

/// Throws CommandError(kUsage) unless exactly one of --param and --cases is given, or if --seeds
/// is given with a cases file that has a seed column; kestrel::Error at a malformed range or
/// cases file.
SweepPlan plan_sweep(const SweepArgs& args);

/// Both graphs on seeds 1..seeds: job 2(s-1) is A with seed s, job 2(s-1)+1 is B with seed s.
struct AbPlan {
  std::vector<std::string> sets_a, sets_b;  ///< the shared overrides, then each side's own
  std::vector<BatchJob> jobs;
};

AbPlan plan_ab(const AbArgs& args);

/// The number of runs at once: `jobs`, or one per core when it is 0.
int jobs_or_cores(int jobs);

}  // namespace kestrel::cli
