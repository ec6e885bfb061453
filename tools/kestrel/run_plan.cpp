#include "run_plan.hpp"

#include <fmt/format.h>

#include <cmath>
#include <sstream>
#include <thread>

#include "case_table.hpp"
#include "command_errors.hpp"
#include "kestrel/error.hpp"

namespace kestrel::cli {

SweptParam parse_range(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos) throw Error("--param needs node.param=start:stop:step, not '" + text + "'");
  SweptParam p{text.substr(0, eq), {}};
  double a = 0, b = 0, step = 0;
  char c1 = 0, c2 = 0;
  std::istringstream in(text.substr(eq + 1));
  if (!(in >> a >> c1 >> b >> c2 >> step) || c1 != ':' || c2 != ':' || step <= 0 || b < a)
    throw Error("--param " + text + ": expected start:stop:step with start <= stop and step > 0");
  // Each value from the start, not by adding steps, so that rounding errors do not pile up.
  for (int i = 0;; ++i) {
    const double v = a + i * step;
    if (v > b + step * 1e-9) break;
    p.values.push_back(fmt::format("{}", std::round(v * 1e9) / 1e9));
  }
  return p;
}

std::vector<std::string> run_args(const std::string& graph, const std::vector<std::string>& sets, int seed,
                                  const std::optional<double>& duration, const std::filesystem::path& report_dir) {
  std::vector<std::string> args = {
      "run", graph, "--seed", std::to_string(seed), "--report", report_dir.string(), "--no-progress"};
  for (const auto& s : sets) {
    args.push_back("--set");
    args.push_back(s);
  }
  if (duration) {
    args.push_back("--duration");
    args.push_back(fmt::format("{}", *duration));
  }
  return args;
}

std::vector<std::string> SweepPlan::sets_for(std::size_t point) const {
  std::vector<std::string> sets = overrides;
  for (std::size_t i = 0; i < params.size(); ++i)
    if (!grid[point][i].empty()) sets.push_back(params[i].key + "=" + grid[point][i]);
  return sets;
}

namespace {

// Every combination of the swept values.
void plan_grid(const SweepArgs& args, SweepPlan& plan) {
  for (const auto& p : args.params) plan.params.push_back(parse_range(p));
  plan.seeds = args.seeds.value_or(1);
  plan.grid = {{}};
  for (const auto& p : plan.params) {
    std::vector<std::vector<std::string>> next;
    for (const auto& combo : plan.grid)
      for (const auto& v : p.values) {
        auto c = combo;
        c.push_back(v);
        next.push_back(c);
      }
    plan.grid = next;
  }
}

// The rows of the cases file; returns each case's own seed if the file gives them.
std::vector<int> plan_cases(const SweepArgs& args, SweepPlan& plan) {
  CaseTable table = read_case_table(args.cases);
  if (table.has_seeds && args.seeds)
    throw CommandError(kUsage, "--seeds cannot be given with " + args.cases +
                                   ": its seed column gives each case its seed (drop the column to run "
                                   "every case with seeds 1..N)");
  plan.cases_file = args.cases;
  plan.case_lines = table.lines;
  plan.case_seeds = table.has_seeds;
  plan.seeds = table.has_seeds ? 1 : args.seeds.value_or(1);
  for (std::size_t k = 0; k < table.keys.size(); ++k) {
    SweptParam p{table.keys[k], {}};
    for (const auto& row : table.values) p.values.push_back(row[k]);
    plan.params.push_back(p);
  }
  plan.grid = std::move(table.values);
  return table.seeds;
}

}  // namespace

SweepPlan plan_sweep(const SweepArgs& args) {
  if (!args.params.empty() && !args.cases.empty())
    throw CommandError(kUsage, "give either --param (a grid) or --cases (a table of cases), not both");
  if (args.params.empty() && args.cases.empty())
    throw CommandError(kUsage,
                       "give the points to run: --param node.param=start:stop:step (repeatable: a grid) or "
                       "--cases FILE.csv (a table of cases)");
  SweepPlan plan;
  plan.overrides = args.overrides;
  std::vector<int> case_seeds;
  if (args.cases.empty())
    plan_grid(args, plan);
  else
    case_seeds = plan_cases(args, plan);
  const std::filesystem::path runs = std::filesystem::path(args.report_dir) / "runs";
  for (std::size_t g = 0; g < plan.grid.size(); ++g) {
    std::vector<int> seeds;
    if (plan.case_seeds)
      seeds = {case_seeds[g]};
    else
      for (int seed = 1; seed <= plan.seeds; ++seed) seeds.push_back(seed);
    for (const int seed : seeds) {
      const auto dir = runs / fmt::format("{:03}_seed{}", g, seed);
      plan.jobs.push_back({run_args(args.graph, plan.sets_for(g), seed, args.duration, dir), dir});
      plan.job_points.push_back(g);
      plan.job_seeds.push_back(seed);
    }
  }
  return plan;
}

AbPlan plan_ab(const AbArgs& args) {
  if (args.seeds < 2) throw Error("an A/B comparison needs at least 2 seeds");
  AbPlan plan;
  plan.sets_a = plan.sets_b = args.overrides;
  plan.sets_a.insert(plan.sets_a.end(), args.overrides_a.begin(), args.overrides_a.end());
  plan.sets_b.insert(plan.sets_b.end(), args.overrides_b.begin(), args.overrides_b.end());
  const std::filesystem::path runs = std::filesystem::path(args.report_dir) / "runs";
  for (int seed = 1; seed <= args.seeds; ++seed) {
    const auto dir_a = runs / fmt::format("A_seed{}", seed), dir_b = runs / fmt::format("B_seed{}", seed);
    plan.jobs.push_back({run_args(args.graph_a, plan.sets_a, seed, args.duration, dir_a), dir_a});
    plan.jobs.push_back({run_args(args.graph_b, plan.sets_b, seed, args.duration, dir_b), dir_b});
  }
  return plan;
}

int jobs_or_cores(int jobs) {
  return jobs > 0 ? jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

}  // namespace kestrel::cli
