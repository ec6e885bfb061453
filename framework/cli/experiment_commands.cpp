// kestrel sweep and kestrel ab: plan the runs, check the graph once, run them in parallel,
// summarise, write the outputs.
#include <cstdio>

#include "batch_runs.hpp"
#include "commands.hpp"
#include "experiment_analysis.hpp"
#include "experiment_output.hpp"
#include "kestrel/error.hpp"
#include "kestrel/runtime/graph.hpp"
#include "kestrel/runtime/plugin_host.hpp"
#include "run_plan.hpp"

namespace kestrel::cli {

namespace {

// Fails early, before hundreds of runs, if the graph or an override is wrong.
void check_graph(const std::string& graph, const std::vector<std::string>& overrides) {
  const GraphSource source = GraphSource::from_file(graph);
  PluginHost plugins;
  plugins.load_search_path(source.plugin_paths());
  const BuildResult r = build_graph(source, plugins.registry(), overrides);
  if (r.diagnostics.has_errors()) throw Error(r.diagnostics.str() + graph + ": invalid, nothing was run");
}

}  // namespace

int sweep_command(const SweepArgs& args) {
  try {
    const SweepPlan plan = plan_sweep(args);
    check_graph(args.graph, plan.sets_for(0));
    std::fprintf(stderr, "[kestrel] sweep: %zu grid points x %d seeds = %zu runs\n", plan.grid.size(), plan.seeds,
                 plan.jobs.size());
    const auto results = run_batch(plan.jobs, jobs_or_cores(args.jobs));
    const SweepSummary summary = summarise_sweep(plan, results);
    const std::string md = write_sweep_outputs(args.report_dir, args.graph, plan, summary);
    std::fputs(md.c_str(), stdout);
    return summary.failed ? kRunFailed : kOk;
  } catch (const Error& e) {
    std::fprintf(stderr, "kestrel sweep: %s\n", e.what());
    return kUsage;
  }
}

int ab_command(const AbArgs& args) {
  try {
    const AbPlan plan = plan_ab(args);
    check_graph(args.graph_a, plan.sets_a);
    check_graph(args.graph_b, plan.sets_b);
    const auto results = run_batch(plan.jobs, jobs_or_cores(args.jobs));
    const AbSummary summary = summarise_ab(results);
    const std::string md = write_ab_outputs(args.report_dir, args, summary);
    std::fputs(md.c_str(), stdout);
    return summary.failed_seeds ? kRunFailed : kOk;
  } catch (const Error& e) {
    std::fprintf(stderr, "kestrel ab: %s\n", e.what());
    return kUsage;
  }
}

}  // namespace kestrel::cli
