#include "run_plan.hpp"

#include <fmt/format.h>

#include <cmath>
#include <sstream>
#include <thread>

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
  for (std::size_t i = 0; i < params.size(); ++i) sets.push_back(params[i].key + "=" + grid[point][i]);
  return sets;
}

SweepPlan plan_sweep(const SweepArgs& args) {
  SweepPlan plan;
  for (const auto& p : args.params) plan.params.push_back(parse_range(p));
  if (plan.params.empty()) throw Error("give at least one --param node.param=start:stop:step");
  plan.seeds = args.seeds;
  plan.overrides = args.overrides;
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
  const std::filesystem::path runs = std::filesystem::path(args.report_dir) / "runs";
  for (std::size_t g = 0; g < plan.grid.size(); ++g)
    for (int seed = 1; seed <= args.seeds; ++seed) {
      const auto dir = runs / fmt::format("{:03}_seed{}", g, seed);
      plan.jobs.push_back({run_args(args.graph, plan.sets_for(g), seed, args.duration, dir), dir});
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
