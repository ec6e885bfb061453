#include "experiment_output.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "csv_format.hpp"
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
  for (const auto& p : plan.params) csv += csv_cell(p.key) + ",";
  csv += "seed,exit_code";
  for (const auto& m : summary.metric_names) csv.append(",").append(csv_cell(m));  // "," + s: GCC 12 -O3 -Wrestrict
  csv += "\n";
  for (std::size_t j = 0; j < summary.runs.size(); ++j) {
    // A case's value may hold commas (a YAML list): quoted, as RFC 4180 has it.
    for (const auto& v : plan.grid[plan.point_of(j)]) csv += csv_cell(v) + ",";
    csv += fmt::format("{},{}", plan.seed_of(j), summary.exit_codes[j]);
    for (const auto& m : summary.metric_names) {
      const auto it = summary.runs[j].find(m);
      // Missing or undefined (null in the report): an empty cell, which `kestrel plot` draws as a gap.
      csv += it == summary.runs[j].end() || std::isnan(it->second) ? "," : fmt::format(",{}", it->second);
    }
    csv += "\n";
  }
  return csv;
}

// A mean over seeds, saying how many seeds left the metric undefined.
std::string mean_cell(const SweepSummary& summary, std::size_t point, const std::string& metric) {
  const auto it = summary.undefined[point].find(metric);
  const std::size_t undefined = it == summary.undefined[point].end() ? 0 : it->second;
  const std::string value = number(summary.means[point].at(metric));
  if (undefined == 0 || std::isnan(summary.means[point].at(metric))) return value;
  return fmt::format("{} ({} of {} n/a)", value, undefined, summary.runs_per_point[point]);
}

bool any_undefined(const SweepSummary& summary) {
  for (const auto& per_point : summary.undefined)
    for (const auto& [m, n] : per_point)
      if (n > 0) return true;
  return false;
}

// The point's swept values, as --set would take them; a case also by its number (and so its
// runs/ folder).
std::string point_text(const SweepPlan& plan, std::size_t point) {
  std::vector<std::string> parts;
  for (std::size_t i = 0; i < plan.params.size(); ++i)
    if (!plan.grid[point][i].empty()) parts.push_back(plan.params[i].key + "=" + plan.grid[point][i]);
  const std::string values = fmt::format("{}", fmt::join(parts, ", "));
  if (!plan.from_cases()) return values;
  return values.empty() ? fmt::format("case {}", point) : fmt::format("case {} ({})", point, values);
}

std::optional<double> number_in(const std::string& text) {
  try {
    std::size_t used = 0;
    const double v = std::stod(text, &used);
    if (used == text.size()) return v;
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

// What sweep.png plots the metrics against: the first swept parameter where every point's value
// is a number, else the point's index (always for cases: random rows have no order to show).
struct PlotAxis {
  std::string name;  ///< the parameter, "case" or "point"
  bool by_value = false;
  std::vector<double> x;  ///< per point
};

PlotAxis plot_axis(const SweepPlan& plan) {
  PlotAxis axis{plan.from_cases() ? "case" : plan.params[0].key, !plan.from_cases(), {}};
  for (std::size_t g = 0; g < plan.grid.size() && axis.by_value; ++g) {
    const auto v = number_in(plan.grid[g][0]);
    if (v)
      axis.x.push_back(*v);
    else
      axis.by_value = false;
  }
  if (axis.by_value) return axis;
  if (!plan.from_cases()) axis.name = "point";
  axis.x.clear();
  for (std::size_t g = 0; g < plan.grid.size(); ++g) axis.x.push_back(static_cast<double>(g));
  return axis;
}

// "3 seeds per point", or where the cases come from and how each runs.
std::string runs_text(const SweepPlan& plan) {
  if (!plan.from_cases()) return fmt::format("{} seeds per point", plan.seeds);
  const std::string cases = fmt::format("{} cases from {}", plan.grid.size(), plan.cases_file);
  return plan.case_seeds ? cases + ", each with its own seed" : fmt::format("{} x {} seeds", cases, plan.seeds);
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

  const bool one_run_per_case = plan.from_cases() && plan.case_seeds;
  std::string md = fmt::format("# Sweep of {}\n\n{} runs ({}){}.\n\n", graph, plan.jobs.size(), runs_text(plan),
                               one_run_per_case ? "" : "; mean over seeds");
  // A column per metric that changes with the swept values; the others fit in a sentence. Cases
  // are numbered as their runs/ folders, with their seeds where the file gives them.
  const std::set<std::string>& shown = summary.varying.empty() ? summary.metric_names : summary.varying;
  std::vector<std::string> columns;
  if (plan.from_cases()) columns.push_back("case");
  if (one_run_per_case) columns.push_back("seed");
  for (const auto& p : plan.params) columns.push_back(p.key);
  for (const auto& m : shown) columns.push_back(summary.meta.label(m));
  md += fmt::format("| {} |\n|", fmt::join(columns, " | "));
  for (std::size_t i = 0; i < columns.size(); ++i) md += "---|";
  md += "\n";
  for (std::size_t g = 0; g < plan.grid.size(); ++g) {
    md += "|";
    if (plan.from_cases()) md += fmt::format(" {} |", g);
    if (one_run_per_case) md += fmt::format(" {} |", plan.seed_of(g));  // one job per case
    for (const auto& v : plan.grid[g]) md += " " + (v.empty() ? std::string("not set") : v) + " |";
    for (const auto& m : shown) md += fmt::format(" {} |", mean_cell(summary, g, m));
    md += "\n";
  }
  const char* point = plan.from_cases() ? "case" : "point";
  std::vector<std::string> same;
  for (const auto& m : summary.metric_names)
    if (!shown.count(m)) same.push_back(summary.meta.label(m) + " = " + mean_cell(summary, 0, m));
  if (!same.empty())
    md += fmt::format("\nThe same {} {}: {}.\n", plan.from_cases() ? "in every" : "at every", point,
                      fmt::join(same, ", "));
  if (!summary.best.empty()) {
    md += fmt::format("\nBest {} per metric (which way is better: the reports' metrics_meta):\n\n", point);
    for (const auto& [m, best] : summary.best)
      md += fmt::format("- {} ({}): {} at {}{}\n", summary.meta.label(m), summary.meta.better_text(m),
                        number(best.value), point_text(plan, best.point),
                        best.ties ? fmt::format(" and {} other {}(s)", best.ties, point) : "");
  }

  // Metrics against the first swept parameter (other parameters mixed in), or per point.
  const PlotAxis axis = plot_axis(plan);
  const std::string against = (axis.by_value ? " against " : " per ") + axis.name;
  const auto plotted = judged_first(std::vector<std::string>(shown.begin(), shown.end()), summary.meta);
  std::vector<plot::Panel> panels;
  for (const auto& m : plotted) {
    if (panels.size() == kSweepPanels) break;
    const std::string better = summary.meta.better_text(m);
    // Points in no order (cases, words) are not joined by lines.
    plot::Series s{m,
                   {},
                   {},
                   axis.by_value ? plot::Series::Style::line_and_points : plot::Series::Style::points,
                   plot::palette(panels.size()),
                   axis.by_value ? 2 : 3};
    s.x = axis.x;
    for (std::size_t g = 0; g < plan.grid.size(); ++g) s.y.push_back(summary.means[g].at(m));
    panels.push_back(
        {m + against + (better.empty() ? "" : " (" + better + ")"), axis.name, summary.meta.label(m), {s}});
  }
  if (!panels.empty()) {
    write_png(dir / "sweep.png", panels, 900, 260);
    md += "\n![metrics" + against + "](sweep.png)\n";
    if (plotted.size() > panels.size())
      md += fmt::format("\nsweep.png shows {} of {} metrics{}.\n", panels.size(), plotted.size(),
                        axis.by_value ? fmt::format("; `kestrel plot sweep.csv --x {} --y METRIC` draws any", axis.name)
                                      : std::string("; sweep.csv has every metric of every run"));
  }
  if (any_undefined(summary))
    md +=
        "\nn/a: undefined (the report gave null: nothing to measure it on); \"k of n n/a\": the mean is over the "
        "other seeds.\n";
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
  bool any_magnitude = false, any_unjudged = false, any_undefined = false;
  for (const auto& row : summary.rows) {
    const PairedDifference& d = row.difference;
    nlohmann::json entry = {{"mean_a", d.mean_a},
                            {"mean_b", d.mean_b},
                            {"difference", d.mean_difference},
                            {"ci95", {d.ci95.low, d.ci95.high}},
                            {"better", row.better.empty() ? nlohmann::json() : nlohmann::json(row.better)}};
    if (row.by_magnitude) entry["by_magnitude"] = true;
    entry["seeds"] = row.seeds.size();
    entry["undefined_seeds"] = row.undefined;
    any_undefined = any_undefined || row.undefined > 0;
    json["metrics"][row.metric] = entry;
    any_magnitude = any_magnitude || row.by_magnitude;
    any_unjudged = any_unjudged || row.better.empty();
    const std::string undefined =
        row.undefined ? fmt::format(" ({} of {} seeds n/a)", row.undefined, row.undefined + row.seeds.size()) : "";
    if (row.seeds.empty())
      md += fmt::format("| {}{} | n/a | n/a | n/a | n/a | n/a |\n", meta.label(row.metric), undefined);
    else
      md += fmt::format("| {}{}{} | {:.4g} | {:.4g} | {:+.4g} | [{:+.4g}, {:+.4g}] | {} |\n", meta.label(row.metric),
                        row.by_magnitude ? " (magnitude)" : "", undefined, d.mean_a, d.mean_b, d.mean_difference,
                        d.ci95.low, d.ci95.high, row.better.empty() ? "n/a" : row.better);
  }
  if (any_undefined)
    md +=
        "\n(k of n seeds n/a): the metric was undefined (null) in A or B on k seeds; the means, difference and "
        "interval are over the others.\n";
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
