#include "experiment_output.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cstdio>

#include "kestrel/plot/line_plot.hpp"
#include "output_files.hpp"

namespace kestrel::cli {

namespace {

std::string sweep_csv(const SweepPlan& plan, const SweepSummary& summary) {
  std::string csv;
  for (const auto& p : plan.params) csv += p.key + ",";
  csv += "seed,exit_code";
  for (const auto& m : summary.metric_names) csv += "," + m;
  csv += "\n";
  for (std::size_t j = 0; j < summary.runs.size(); ++j) {
    for (const auto& v : plan.grid[plan.point_of(j)]) csv += v + ",";
    csv += fmt::format("{},{}", plan.seed_of(j), summary.exit_codes[j]);
    for (const auto& m : summary.metric_names) {
      const auto it = summary.runs[j].find(m);
      csv += it == summary.runs[j].end() ? "," : fmt::format(",{}", it->second);
    }
    csv += "\n";
  }
  return csv;
}

}  // namespace

std::string write_sweep_outputs(const std::filesystem::path& dir, const std::string& graph, const SweepPlan& plan,
                                const SweepSummary& summary) {
  make_folder(dir);
  write_file(dir / "sweep.csv", sweep_csv(plan, summary));

  std::string md = fmt::format("# Sweep of {}\n\n{} runs ({} seeds per point); mean over seeds.\n\n", graph,
                               plan.jobs.size(), plan.seeds);
  std::vector<std::string> shown;
  for (const auto& m : summary.metric_names)
    if (headline(m)) shown.push_back(m);
  md += "|";
  for (const auto& p : plan.params) md += " " + p.key + " |";
  for (const auto& m : shown) md += " " + m + " |";
  md += "\n|";
  for (std::size_t i = 0; i < plan.params.size() + shown.size(); ++i) md += "---|";
  md += "\n";
  for (std::size_t g = 0; g < plan.grid.size(); ++g) {
    md += "|";
    for (const auto& v : plan.grid[g]) md += " " + v + " |";
    for (const auto& m : shown) {
      const double mean = summary.means[g].at(m);
      md += std::isnan(mean) ? " n/a |" : fmt::format(" {:.4g} |", mean);
    }
    md += "\n";
  }
  // One plot: every shown metric against the first swept parameter (other parameters mixed in).
  std::vector<plot::Panel> panels;
  for (const auto& m : shown) {
    const std::string last = m.substr(m.rfind('.') + 1);
    if (last != "mota" && last != "idf1" && last != "precision" && last != "recall" && last != "rmse_m") continue;
    plot::Series s{m, {}, {}, plot::Series::Style::line_and_points, plot::palette(panels.size()), 2};
    for (std::size_t g = 0; g < plan.grid.size(); ++g) {
      s.x.push_back(std::stod(plan.grid[g][0]));
      s.y.push_back(summary.means[g].at(m));
    }
    panels.push_back({m + " against " + plan.params[0].key, plan.params[0].key, m, {s}});
  }
  if (!panels.empty()) {
    write_png(dir / "sweep.png", panels, 900, 260);
    md += "\n![metrics against " + plan.params[0].key + "](sweep.png)\n";
  }
  if (summary.failed) md += fmt::format("\n{} run(s) failed; see runs/*/run.log.\n", summary.failed);
  write_file(dir / "sweep.md", md);
  return md;
}

std::string write_ab_outputs(const std::filesystem::path& dir, const AbArgs& args, const AbSummary& summary) {
  nlohmann::json json = {{"a", args.graph_a},
                         {"b", args.graph_b},
                         {"set", args.overrides},
                         {"set_a", args.overrides_a},
                         {"set_b", args.overrides_b},
                         {"seeds", args.seeds},
                         {"failed_seeds", summary.failed_seeds},
                         {"metrics", nlohmann::json::object()}};
  auto described = [](const std::string& graph, const std::vector<std::string>& sets) {
    return sets.empty() ? graph : fmt::format("{} with {}", graph, fmt::join(sets, ", "));
  };
  std::string md = fmt::format(
      "# A/B: {} (A) against {} (B)\n\n{} seeds, paired by seed{}. Difference = B - A, with its 95% confidence "
      "interval (Student's t).\n\n| metric | mean A | mean B | B - A | 95% CI | better "
      "|\n|---|---:|---:|---:|---|---|\n",
      described(args.graph_a, args.overrides_a), described(args.graph_b, args.overrides_b), args.seeds,
      args.overrides.empty() ? "" : fmt::format(", both with {}", fmt::join(args.overrides, ", ")));
  std::vector<plot::Panel> panels;  // per-seed values of the metrics that differ, up to four
  for (const auto& row : summary.rows) {
    const PairedDifference& d = row.difference;
    json["metrics"][row.metric] = {{"mean_a", d.mean_a},
                                   {"mean_b", d.mean_b},
                                   {"difference", d.mean_difference},
                                   {"ci95", {d.ci95.low, d.ci95.high}},
                                   {"better", row.better}};
    if (row.by_magnitude) json["metrics"][row.metric]["by_magnitude"] = true;
    const std::string name = row.by_magnitude ? row.metric + " (magnitude)" : row.metric;
    md += fmt::format("| {} | {:.4g} | {:.4g} | {:+.4g} | [{:+.4g}, {:+.4g}] | {} |\n", name, d.mean_a, d.mean_b,
                      d.mean_difference, d.ci95.low, d.ci95.high, row.better);
    if (row.better != "equal" && panels.size() < 4) {
      plot::Panel panel{fmt::format("{} per seed (better: {})", row.metric, row.better), "seed", row.metric, {}};
      for (const auto& [name, side] : {std::pair{"A", 0}, std::pair{"B", 1}}) {
        plot::Series series{name, {}, {}, plot::Series::Style::points, plot::palette(side), 3};
        for (std::size_t i = 0; i < row.seeds.size(); ++i) {
          series.x.push_back(row.seeds[i]);
          series.y.push_back(side == 0 ? row.a[i] : row.b[i]);
        }
        panel.series.push_back(series);
      }
      panels.push_back(panel);
    }
  }
  if (summary.failed_seeds)
    md += fmt::format("\n{} seed(s) left out: a run failed (see runs/*/run.log).\n", summary.failed_seeds);
  make_folder(dir);
  if (!panels.empty()) {
    write_png(dir / "ab.png", panels, 900, 260);
    md += "\n![A and B seed by seed](ab.png)\n";
  }
  write_file(dir / "ab.md", md);
  write_file(dir / "ab.json", json.dump(2) + "\n");
  return md;
}

}  // namespace kestrel::cli
