#include "experiment_output.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>

#include "kestrel/plot/line_plot.hpp"
#include "output_files.hpp"

namespace kestrel::cli {

namespace {

// Panels in a summary plot: a picture of many more gets too tall to read.
constexpr std::size_t kSweepPanels = 6;
constexpr std::size_t kAbPanels = 4;

std::string number(double v) { return std::isnan(v) ? "n/a" : fmt::format("{:.4g}", v); }

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

// The point's swept values, as --set would take them.
std::string point_text(const SweepPlan& plan, std::size_t point) {
  std::vector<std::string> parts;
  for (std::size_t i = 0; i < plan.params.size(); ++i) parts.push_back(plan.params[i].key + "=" + plan.grid[point][i]);
  return fmt::format("{}", fmt::join(parts, ", "));
}

// Judged metrics first (their plots say which way is better), each group in name order.
std::vector<std::string> judged_first(std::vector<std::string> metrics, const MetricsMeta& meta) {
  std::stable_partition(metrics.begin(), metrics.end(), [&](const std::string& m) { return meta.direction(m) != 0; });
  return metrics;
}

}  // namespace

std::string write_sweep_outputs(const std::filesystem::path& dir, const std::string& graph, const SweepPlan& plan,
                                const SweepSummary& summary) {
  make_folder(dir);
  write_file(dir / "sweep.csv", sweep_csv(plan, summary));
  // Beside the CSV, so that `kestrel plot sweep.csv` labels its axes with the units.
  write_file(dir / "metrics_meta.json", nlohmann::json{{"metrics_meta", summary.meta.to_json()}}.dump(2) + "\n");

  std::string md = fmt::format("# Sweep of {}\n\n{} runs ({} seeds per point); mean over seeds.\n\n", graph,
                               plan.jobs.size(), plan.seeds);
  // A column per metric that changes with the swept values; the others fit in a sentence.
  const std::set<std::string>& shown = summary.varying.empty() ? summary.metric_names : summary.varying;
  md += "|";
  for (const auto& p : plan.params) md += " " + p.key + " |";
  for (const auto& m : shown) md += fmt::format(" {} |", summary.meta.label(m));
  md += "\n|";
  for (std::size_t i = 0; i < plan.params.size() + shown.size(); ++i) md += "---|";
  md += "\n";
  for (std::size_t g = 0; g < plan.grid.size(); ++g) {
    md += "|";
    for (const auto& v : plan.grid[g]) md += " " + v + " |";
    for (const auto& m : shown) md += fmt::format(" {} |", number(summary.means[g].at(m)));
    md += "\n";
  }
  std::vector<std::string> same;
  for (const auto& m : summary.metric_names)
    if (!shown.count(m)) same.push_back(summary.meta.label(m) + " = " + number(summary.means[0].at(m)));
  if (!same.empty()) md += fmt::format("\nThe same at every point: {}.\n", fmt::join(same, ", "));
  if (!summary.best.empty()) {
    md += "\nBest point per metric (which way is better: the reports' metrics_meta):\n\n";
    for (const auto& [m, best] : summary.best)
      md +=
          fmt::format("- {} ({}): {} at {}{}\n", summary.meta.label(m), summary.meta.better_text(m), number(best.value),
                      point_text(plan, best.point), best.ties ? fmt::format(" and {} other point(s)", best.ties) : "");
  }

  // Metrics against the first swept parameter (other parameters mixed in).
  const std::string& x = plan.params[0].key;
  const auto plotted = judged_first(std::vector<std::string>(shown.begin(), shown.end()), summary.meta);
  std::vector<plot::Panel> panels;
  for (const auto& m : plotted) {
    if (panels.size() == kSweepPanels) break;
    const std::string better = summary.meta.better_text(m);
    plot::Series s{m, {}, {}, plot::Series::Style::line_and_points, plot::palette(panels.size()), 2};
    for (std::size_t g = 0; g < plan.grid.size(); ++g) {
      s.x.push_back(std::stod(plan.grid[g][0]));
      s.y.push_back(summary.means[g].at(m));
    }
    panels.push_back(
        {m + " against " + x + (better.empty() ? "" : " (" + better + ")"), x, summary.meta.label(m), {s}});
  }
  if (!panels.empty()) {
    write_png(dir / "sweep.png", panels, 900, 260);
    md += "\n![metrics against " + x + "](sweep.png)\n";
    if (plotted.size() > panels.size())
      md += fmt::format("\nsweep.png shows {} of {} metrics; `kestrel plot sweep.csv --x {} --y METRIC` draws any.\n",
                        panels.size(), plotted.size(), x);
  }
  if (summary.failed) md += fmt::format("\n{} run(s) failed; see runs/*/run.log.\n", summary.failed);
  write_file(dir / "sweep.md", md);
  return md;
}

std::string write_ab_outputs(const std::filesystem::path& dir, const AbArgs& args, const AbSummary& summary) {
  const MetricsMeta& meta = summary.meta;
  nlohmann::json json = {{"a", args.graph_a},
                         {"b", args.graph_b},
                         {"set", args.overrides},
                         {"set_a", args.overrides_a},
                         {"set_b", args.overrides_b},
                         {"seeds", args.seeds},
                         {"failed_seeds", summary.failed_seeds},
                         {"metrics", nlohmann::json::object()},
                         {"metrics_meta", meta.to_json()}};
  auto described = [](const std::string& graph, const std::vector<std::string>& sets) {
    return sets.empty() ? graph : fmt::format("{} with {}", graph, fmt::join(sets, ", "));
  };
  std::string md = fmt::format(
      "# A/B: {} (A) against {} (B)\n\n{} seeds, paired by seed{}. Difference = B - A, with its 95% confidence "
      "interval (Student's t).\n\n| metric | mean A | mean B | B - A | 95% CI | better "
      "|\n|---|---:|---:|---:|---|---|\n",
      described(args.graph_a, args.overrides_a), described(args.graph_b, args.overrides_b), args.seeds,
      args.overrides.empty() ? "" : fmt::format(", both with {}", fmt::join(args.overrides, ", ")));
  bool any_magnitude = false, any_unjudged = false;
  for (const auto& row : summary.rows) {
    const PairedDifference& d = row.difference;
    nlohmann::json entry = {{"mean_a", d.mean_a},
                            {"mean_b", d.mean_b},
                            {"difference", d.mean_difference},
                            {"ci95", {d.ci95.low, d.ci95.high}},
                            {"better", row.better.empty() ? nlohmann::json() : nlohmann::json(row.better)}};
    if (row.by_magnitude) entry["by_magnitude"] = true;
    json["metrics"][row.metric] = entry;
    any_magnitude = any_magnitude || row.by_magnitude;
    any_unjudged = any_unjudged || row.better.empty();
    md += fmt::format("| {}{} | {:.4g} | {:.4g} | {:+.4g} | [{:+.4g}, {:+.4g}] | {} |\n", meta.label(row.metric),
                      row.by_magnitude ? " (magnitude)" : "", d.mean_a, d.mean_b, d.mean_difference, d.ci95.low,
                      d.ci95.high, row.better.empty() ? "n/a" : row.better);
  }
  if (any_magnitude) md += "\n(magnitude): means and difference of |value|, as the reports' metrics_meta asks.\n";
  if (any_unjudged) md += "\nn/a: the reports' metrics_meta does not say which way is better.\n";
  if (!meta.conflicts().empty())
    md += fmt::format("\nThe runs' metrics_meta disagree on {}; no verdict where the direction differs.\n",
                      fmt::join(meta.conflicts(), ", "));
  if (summary.failed_seeds)
    md += fmt::format("\n{} seed(s) left out: a run failed (see runs/*/run.log).\n", summary.failed_seeds);

  // Seed by seed, the metrics that differ: the significant ones first.
  std::vector<const AbRow*> differing;
  for (const auto& row : summary.rows)
    if (row.better != "equal") differing.push_back(&row);
  auto rank = [](const AbRow* r) { return r->better == "A" || r->better == "B" ? 0 : r->better.empty() ? 2 : 1; };
  std::stable_sort(differing.begin(), differing.end(),
                   [&](const AbRow* l, const AbRow* r) { return rank(l) < rank(r); });
  std::vector<plot::Panel> panels;
  for (const AbRow* row : differing) {
    if (panels.size() == kAbPanels) break;
    plot::Panel panel{row->better.empty() ? row->metric + " per seed"
                                          : fmt::format("{} per seed (better: {})", row->metric, row->better),
                      "seed",
                      meta.label(row->metric),
                      {}};
    for (const auto& [name, side] : {std::pair{"A", 0}, std::pair{"B", 1}}) {
      plot::Series series{name, {}, {}, plot::Series::Style::points, plot::palette(side), 3};
      for (std::size_t i = 0; i < row->seeds.size(); ++i) {
        series.x.push_back(row->seeds[i]);
        series.y.push_back(side == 0 ? row->a[i] : row->b[i]);
      }
      panel.series.push_back(series);
    }
    panels.push_back(panel);
  }
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
