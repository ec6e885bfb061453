// kestrel sweep and kestrel ab: plan the runs, check the graph first, run them in parallel here
// or as a Slurm job array, summarise, write the outputs; kestrel collect: the same outputs from a
// batch Slurm ran.
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
#include "slurm_batch.hpp"

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

namespace {

std::string absolute(const std::string& path) {
  return path.empty() ? path : std::filesystem::absolute(path).lexically_normal().string();
}

// A Slurm task runs in the submission's folder, but a collector may run anywhere: every path of a
// submitted batch is absolute. Shell quoting of the task's command line cannot hold a quote.
void make_paths_absolute(std::string& graph, std::string& report_dir) {
  graph = absolute(graph);
  report_dir = absolute(report_dir);
  if (report_dir.find('\'') != std::string::npos)
    throw CommandError(kUsage, "--report: a Slurm batch's folder cannot hold a ' (" + report_dir + ")");
}

nlohmann::json sweep_json(const SweepArgs& a) {
  return {{"command", "sweep"},
          {"graph", a.graph},
          {"params", a.params},
          {"cases", a.cases},
          {"set", a.overrides},
          {"seeds", a.seeds ? nlohmann::json(*a.seeds) : nlohmann::json(nullptr)},
          {"duration", a.duration ? nlohmann::json(*a.duration) : nlohmann::json(nullptr)},
          {"report_dir", a.report_dir}};
}

SweepArgs sweep_args(const nlohmann::json& j) {
  SweepArgs a;
  a.graph = j.at("graph");
  a.params = j.at("params").get<std::vector<std::string>>();
  a.cases = j.at("cases");
  a.overrides = j.at("set").get<std::vector<std::string>>();
  if (!j.at("seeds").is_null()) a.seeds = j.at("seeds").get<int>();
  if (!j.at("duration").is_null()) a.duration = j.at("duration").get<double>();
  a.report_dir = j.at("report_dir");
  return a;
}

nlohmann::json ab_json(const AbArgs& a) {
  return {{"command", "ab"},
          {"a", a.graph_a},
          {"b", a.graph_b},
          {"set", a.overrides},
          {"set_a", a.overrides_a},
          {"set_b", a.overrides_b},
          {"seeds", a.seeds},
          {"duration", a.duration ? nlohmann::json(*a.duration) : nlohmann::json(nullptr)},
          {"report_dir", a.report_dir}};
}

AbArgs ab_args(const nlohmann::json& j) {
  AbArgs a;
  a.graph_a = j.at("a");
  a.graph_b = j.at("b");
  a.overrides = j.at("set").get<std::vector<std::string>>();
  a.overrides_a = j.at("set_a").get<std::vector<std::string>>();
  a.overrides_b = j.at("set_b").get<std::vector<std::string>>();
  a.seeds = j.at("seeds");
  if (!j.at("duration").is_null()) a.duration = j.at("duration").get<double>();
  a.report_dir = j.at("report_dir");
  return a;
}

// A Slurm batch's failed runs and tasks that left no exit code (killed or lost), with what Slurm
// says of them, at the end of the summary: counted as failed, never silently missing.
void add_failures(const std::filesystem::path& summary_md, const std::vector<BatchResult>& results, std::string& md) {
  std::string lines;
  for (std::size_t i = 0; i < results.size(); ++i)
    if (!results[i].failure.empty()) lines += fmt::format("- run {}: {}\n", i, results[i].failure);
  if (lines.empty()) return;
  md += "\nRuns that failed or did not end:\n\n" + lines;
  write_file(summary_md, md);
}

int finish_sweep(const SweepArgs& args, const SweepPlan& plan, const std::vector<BatchResult>& results) {
  const SweepSummary summary = summarise_sweep(plan, results);
  std::string md = write_sweep_outputs(args.report_dir, args.graph, plan, summary);
  add_failures(std::filesystem::path(args.report_dir) / "sweep.md", results, md);
  std::fputs(md.c_str(), stdout);
  return summary.failed ? kRunFailed : kOk;
}

int finish_ab(const AbArgs& args, const std::vector<BatchResult>& results) {
  const AbSummary summary = summarise_ab(results);
  std::string md = write_ab_outputs(args.report_dir, args, summary);
  add_failures(std::filesystem::path(args.report_dir) / "ab.md", results, md);
  std::fputs(md.c_str(), stdout);
  return summary.failed_seeds ? kRunFailed : kOk;
}

// The batch goes to Slurm; with --wait the results come back here, else the command says how to
// collect them.
std::optional<std::vector<BatchResult>> run_on_slurm(const std::string& report_dir, const nlohmann::json& command,
                                                     const std::vector<BatchJob>& jobs, const BatchBackend& backend) {
  const SlurmJobs ids = submit_to_slurm(report_dir, command, jobs, backend);
  std::fprintf(stderr, "[kestrel] slurm: array job %s (%zu tasks), collector job %s (after it)\n", ids.array.c_str(),
               jobs.size(), ids.collect.c_str());
  if (!backend.wait) {
    std::fprintf(stderr,
                 "[kestrel] the collector writes the results into %s when the tasks end; `squeue -j %s,%s` shows "
                 "them, `kestrel collect %s` summarises again at any time\n",
                 report_dir.c_str(), ids.array.c_str(), ids.collect.c_str(), report_dir.c_str());
    return std::nullopt;
  }
  wait_for_slurm(report_dir, ids, jobs.size());
  return collect_slurm_results(report_dir, jobs);
}

}  // namespace

int sweep_command(const SweepArgs& args_given) {
  return run_command_body("sweep", [&] {
    SweepArgs args = args_given;
    const bool slurm = args.backend.kind == BatchBackend::Kind::slurm;
    if (slurm) {
      make_paths_absolute(args.graph, args.report_dir);
      args.cases = absolute(args.cases);
    }
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
    if (!slurm) return finish_sweep(args, plan, run_batch(plan.jobs, jobs_or_cores(args.jobs)));
    const auto results = run_on_slurm(args.report_dir, sweep_json(args), plan.jobs, args.backend);
    return results ? finish_sweep(args, plan, *results) : kOk;
  });
}

int ab_command(const AbArgs& args_given) {
  return run_command_body("ab", [&] {
    AbArgs args = args_given;
    const bool slurm = args.backend.kind == BatchBackend::Kind::slurm;
    if (slurm) {
      make_paths_absolute(args.graph_a, args.report_dir);
      args.graph_b = absolute(args.graph_b);
    }
    const AbPlan plan = plan_ab(args);
    check_graph(args.graph_a, plan.sets_a);
    check_graph(args.graph_b, plan.sets_b);
    make_folder(std::filesystem::path(args.report_dir) / "runs");
    if (!slurm) return finish_ab(args, run_batch(plan.jobs, jobs_or_cores(args.jobs)));
    const auto results = run_on_slurm(args.report_dir, ab_json(args), plan.jobs, args.backend);
    return results ? finish_ab(args, *results) : kOk;
  });
}

int collect_command(const std::string& dir) {
  return run_command_body("collect", [&] {
    const nlohmann::json command = read_batch_command(dir);
    const std::string kind = command.at("command");
    int code = kOk;
    if (kind == "sweep") {
      const SweepArgs args = sweep_args(command);
      const SweepPlan plan = plan_sweep(args);
      code = finish_sweep(args, plan, collect_slurm_results(args.report_dir, plan.jobs));
    } else if (kind == "ab") {
      const AbArgs args = ab_args(command);
      code = finish_ab(args, collect_slurm_results(args.report_dir, plan_ab(args).jobs));
    } else {
      throw CommandError(kUsage, dir + ": a batch of unknown kind '" + kind + "'");
    }
    write_file(std::filesystem::path(dir) / "batch" / "collected", std::to_string(code) + "\n");
    return code;
  });
}

int batch_task_command(const std::string& dir, std::size_t index) {
  return run_command_body("batch-task", [&] { return run_batch_task(dir, index); });
}

}  // namespace kestrel::cli
