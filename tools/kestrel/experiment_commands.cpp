// kestrel sweep and kestrel ab: plan the runs, check the graph first, run them in parallel,
// summarise, write the outputs.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cstdio>

#include "batch_runs.hpp"
#include "command_errors.hpp"
#include "commands.hpp"
#include "experiment_analysis.hpp"
#include "experiment_output.hpp"
#include "graph_loading.hpp"
#include "output_files.hpp"
#include "run_plan.hpp"

namespace kestrel::cli {

namespace {

// Fails early, before hundreds of runs, if the graph or an override is wrong; exits as `kestrel
// validate` would.
void check_graph(const std::string& graph, const std::vector<std::string>& overrides) {
  if (!load_graph({graph, overrides, {}, {}}, "nothing was run").graph)
    throw CommandError(kInvalidGraph, graph + " is invalid");
}

// A grid's first and last points hold every parameter's smallest and largest value: a value out
// of range shows there. Cases have no such corners: each is checked, and every invalid one is
// named, unless the first is (then the graph itself may be wrong, and once is enough to say so).
void check_points(const std::string& graph, const SweepPlan& plan) {
  if (!plan.from_cases()) {
    check_graph(graph, plan.sets_for(0));
    if (plan.grid.size() > 1) check_graph(graph, plan.sets_for(plan.grid.size() - 1));
    return;
  }
  std::vector<std::string> invalid;
  for (std::size_t c = 0; c < plan.grid.size(); ++c) {
    const std::string name = fmt::format("case {} ({}:{})", c, plan.cases_file, plan.case_lines[c]);
    const std::string not_done = name + " is refused; nothing was run";
    if (!load_graph({graph, plan.sets_for(c), {}, {}}, not_done.c_str()).graph) {
      invalid.push_back(name);
      if (c == 0) break;
    }
  }
  if (!invalid.empty())
    throw CommandError(kInvalidGraph, fmt::format("{} is invalid with {}", graph, fmt::join(invalid, ", ")));
}

}  // namespace

int sweep_command(const SweepArgs& args) {
  return run_command_body("sweep", [&] {
    const SweepPlan plan = plan_sweep(args);
    check_points(args.graph, plan);
    make_folder(std::filesystem::path(args.report_dir) / "runs");
    if (!plan.from_cases())
      std::fprintf(stderr, "[kestrel] sweep: %zu grid points x %d seeds = %zu runs\n", plan.grid.size(), plan.seeds,
                   plan.jobs.size());
    else if (plan.case_seeds)
      std::fprintf(stderr, "[kestrel] sweep: %zu cases from %s, each with its seed = %zu runs\n", plan.grid.size(),
                   plan.cases_file.c_str(), plan.jobs.size());
    else
      std::fprintf(stderr, "[kestrel] sweep: %zu cases from %s x %d seeds = %zu runs\n", plan.grid.size(),
                   plan.cases_file.c_str(), plan.seeds, plan.jobs.size());
    const auto results = run_batch(plan.jobs, jobs_or_cores(args.jobs));
    const SweepSummary summary = summarise_sweep(plan, results);
    const std::string md = write_sweep_outputs(args.report_dir, args.graph, plan, summary);
    std::fputs(md.c_str(), stdout);
    return summary.failed ? kRunFailed : kOk;
  });
}

int ab_command(const AbArgs& args) {
  return run_command_body("ab", [&] {
    const AbPlan plan = plan_ab(args);
    check_graph(args.graph_a, plan.sets_a);
    check_graph(args.graph_b, plan.sets_b);
    make_folder(std::filesystem::path(args.report_dir) / "runs");
    const auto results = run_batch(plan.jobs, jobs_or_cores(args.jobs));
    const AbSummary summary = summarise_ab(results);
    const std::string md = write_ab_outputs(args.report_dir, args, summary);
    std::fputs(md.c_str(), stdout);
    return summary.failed_seeds ? kRunFailed : kOk;
  });
}

}  // namespace kestrel::cli
