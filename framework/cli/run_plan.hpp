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

/// Every combination of the swept values (the grid), each run with seeds 1..seeds. Job j runs
/// grid point j / seeds with seed j % seeds + 1.
struct SweepPlan {
  std::vector<SweptParam> params;
  std::vector<std::vector<std::string>> grid;  ///< per point, one value per param
  int seeds = 1;
  std::vector<std::string> overrides;  ///< the fixed --set values
  std::vector<BatchJob> jobs;

  /// The --set values of a grid point: the fixed overrides, then the swept values.
  std::vector<std::string> sets_for(std::size_t point) const;
  std::size_t point_of(std::size_t job) const { return job / static_cast<std::size_t>(seeds); }
  int seed_of(std::size_t job) const { return static_cast<int>(job % static_cast<std::size_t>(seeds)) + 1; }
};

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
