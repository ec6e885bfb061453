// kestrel sweep and kestrel ab: many runs of graphs, in parallel, summarised with statistics.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>
#include <thread>
#include <tuple>

#include "batch_runs.hpp"
#include "commands.hpp"
#include "kestrel/error.hpp"
#include "kestrel/plot/line_plot.hpp"
#include "kestrel/runtime/graph.hpp"
#include "kestrel/runtime/plugin_host.hpp"

namespace kestrel::cli {

namespace {

struct SweptParam {
  std::string key;  // node.param
  std::vector<std::string> values;
};

SweptParam parse_range(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos) throw Error("--param needs node.param=start:stop:step, not '" + text + "'");
  SweptParam p{text.substr(0, eq), {}};
  double a = 0, b = 0, step = 0;
  char c1 = 0, c2 = 0;
  std::istringstream in(text.substr(eq + 1));
  if (!(in >> a >> c1 >> b >> c2 >> step) || c1 != ':' || c2 != ':' || step <= 0 || b < a)
    throw Error("--param " + text + ": expected start:stop:step with start <= stop and step > 0");
  for (int i = 0;; ++i) {
    const double v = a + i * step;
    if (v > b + step * 1e-9) break;
    p.values.push_back(fmt::format("{}", std::round(v * 1e9) / 1e9));
  }
  return p;
}

// Fails early, before hundreds of runs, if the graph or an override is wrong.
void check_graph(const std::string& graph, const std::vector<std::string>& overrides) {
  const GraphSource source = GraphSource::from_file(graph);
  PluginHost plugins;
  plugins.load_search_path(source.plugin_paths());
  const BuildResult r = build_graph(source, plugins.registry(), overrides);
  if (r.diagnostics.has_errors()) throw Error(r.diagnostics.str() + graph + ": invalid, nothing was run");
}

int jobs_or_cores(int jobs) {
  return jobs > 0 ? jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

std::vector<std::string> run_args(const std::string& graph, const std::vector<std::string>& sets, int seed,
                                  const std::optional<double>& duration, const std::filesystem::path& dir) {
  std::vector<std::string> args = {"run",      graph,        "--seed",       std::to_string(seed),
                                   "--report", dir.string(), "--no-progress"};
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

double t_quantile_975(int df) {
  static const double table[] = {0,     12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228,
                                 2.201, 2.179,  2.160, 2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086, 2.080,
                                 2.074, 2.069,  2.064, 2.060, 2.056, 2.052, 2.048, 2.045, 2.042};
  if (df <= 0) return std::numeric_limits<double>::quiet_NaN();
  return df <= 30 ? table[df] : 1.96 + 2.4 / df;  // close to the exact values beyond 30
}

// The metrics worth a column in a summary table (the CSV and JSON keep every metric).
bool headline(const std::string& metric) {
  static const std::set<std::string> names = {"mota",      "motp_m", "idf1",   "idsw",  "fp",      "fn",
                                              "precision", "recall", "rmse_m", "lag_s", "switches"};
  return names.count(metric.substr(metric.rfind('.') + 1)) > 0 || metric.find(".rmse_m.") != std::string::npos;
}

void write(const std::filesystem::path& file, const std::string& text) {
  std::ofstream out(file);
  out << text;
  if (!out) throw Error("cannot write " + file.string());
}

}  // namespace

int sweep_command(const SweepArgs& args) {
  try {
    std::vector<SweptParam> params;
    for (const auto& p : args.params) params.push_back(parse_range(p));
    if (params.empty()) throw Error("give at least one --param node.param=start:stop:step");
    // The grid: every combination of the swept values, each run with every seed.
    std::vector<std::vector<std::string>> grid = {{}};
    for (const auto& p : params) {
      std::vector<std::vector<std::string>> next;
      for (const auto& combo : grid)
        for (const auto& v : p.values) {
          auto c = combo;
          c.push_back(v);
          next.push_back(c);
        }
      grid = next;
    }
    auto sets_for = [&](const std::vector<std::string>& combo) {
      std::vector<std::string> sets = args.overrides;
      for (std::size_t i = 0; i < params.size(); ++i) sets.push_back(params[i].key + "=" + combo[i]);
      return sets;
    };
    check_graph(args.graph, sets_for(grid.front()));

    const std::filesystem::path dir = args.report_dir;
    std::vector<BatchJob> jobs;
    for (std::size_t g = 0; g < grid.size(); ++g)
      for (int seed = 1; seed <= args.seeds; ++seed)
        jobs.push_back({run_args(args.graph, sets_for(grid[g]), seed, args.duration,
                                 dir / "runs" / fmt::format("{:03}_seed{}", g, seed)),
                        dir / "runs" / fmt::format("{:03}_seed{}", g, seed)});
    std::fprintf(stderr, "[kestrel] sweep: %zu grid points x %d seeds = %zu runs\n", grid.size(), args.seeds,
                 jobs.size());
    const auto results = run_batch(jobs, jobs_or_cores(args.jobs));

    // One CSV row per run, then a Markdown table of means over seeds.
    std::set<std::string> metric_names;
    std::vector<std::map<std::string, double>> metrics;
    for (const auto& r : results) {
      metrics.push_back(report_metrics(r.report));
      for (const auto& [k, _] : metrics.back()) metric_names.insert(k);
    }
    std::string csv;
    for (const auto& p : params) csv += p.key + ",";
    csv += "seed,exit_code";
    for (const auto& m : metric_names) csv += "," + m;
    csv += "\n";
    std::size_t failed = 0;
    for (std::size_t j = 0; j < jobs.size(); ++j) {
      const auto& combo = grid[j / static_cast<std::size_t>(args.seeds)];
      for (const auto& v : combo) csv += v + ",";
      csv += fmt::format("{},{}", j % static_cast<std::size_t>(args.seeds) + 1, results[j].exit_code);
      if (results[j].exit_code != 0) ++failed;
      for (const auto& m : metric_names) {
        const auto it = metrics[j].find(m);
        csv += it == metrics[j].end() ? "," : fmt::format(",{}", it->second);
      }
      csv += "\n";
    }
    std::filesystem::create_directories(dir);
    write(dir / "sweep.csv", csv);

    std::string md = fmt::format("# Sweep of {}\n\n{} runs ({} seeds per point); mean over seeds.\n\n", args.graph,
                                 jobs.size(), args.seeds);
    std::vector<std::string> shown;
    for (const auto& m : metric_names)
      if (headline(m)) shown.push_back(m);
    md += "|";
    for (const auto& p : params) md += " " + p.key + " |";
    for (const auto& m : shown) md += " " + m + " |";
    md += "\n|";
    for (std::size_t i = 0; i < params.size() + shown.size(); ++i) md += "---|";
    md += "\n";
    std::map<std::string, std::pair<std::vector<double>, std::vector<double>>> curves;  // metric -> (x, mean)
    for (std::size_t g = 0; g < grid.size(); ++g) {
      md += "|";
      for (const auto& v : grid[g]) md += " " + v + " |";
      for (const auto& m : shown) {
        double sum = 0;
        int n = 0;
        for (int s = 0; s < args.seeds; ++s) {
          const auto& row = metrics[g * static_cast<std::size_t>(args.seeds) + static_cast<std::size_t>(s)];
          if (auto it = row.find(m); it != row.end()) {
            sum += it->second;
            ++n;
          }
        }
        const double mean = n ? sum / n : std::numeric_limits<double>::quiet_NaN();
        md += n ? fmt::format(" {:.4g} |", mean) : " n/a |";
        curves[m].first.push_back(std::stod(grid[g][0]));
        curves[m].second.push_back(mean);
      }
      md += "\n";
    }
    // One plot: every shown metric against the first swept parameter (other parameters mixed in).
    std::vector<plot::Panel> panels;
    for (const auto& m : shown) {
      const std::string last = m.substr(m.rfind('.') + 1);
      if (last != "mota" && last != "idf1" && last != "precision" && last != "recall" && last != "rmse_m") continue;
      plot::Panel p{m + " against " + params[0].key, params[0].key, m, {}};
      plot::Series s{
          m, curves[m].first, curves[m].second, plot::Series::Style::line_and_points, plot::palette(panels.size()), 2};
      p.series.push_back(s);
      panels.push_back(p);
    }
    if (!panels.empty()) {
      plot::save_png(dir / "sweep.png", panels, 900, 260);
      md += "\n![metrics against " + params[0].key + "](sweep.png)\n";
    }
    if (failed) md += fmt::format("\n{} run(s) failed; see runs/*/run.log.\n", failed);
    write(dir / "sweep.md", md);
    std::fputs(md.c_str(), stdout);
    return failed ? kRunFailed : kOk;
  } catch (const Error& e) {
    std::fprintf(stderr, "kestrel sweep: %s\n", e.what());
    return kUsage;
  }
}

int ab_command(const AbArgs& args) {
  try {
    if (args.seeds < 2) throw Error("an A/B comparison needs at least 2 seeds");
    std::vector<std::string> sets_a = args.overrides, sets_b = args.overrides;
    sets_a.insert(sets_a.end(), args.overrides_a.begin(), args.overrides_a.end());
    sets_b.insert(sets_b.end(), args.overrides_b.begin(), args.overrides_b.end());
    check_graph(args.graph_a, sets_a);
    check_graph(args.graph_b, sets_b);
    const std::filesystem::path dir = args.report_dir;
    std::vector<BatchJob> jobs;
    for (int seed = 1; seed <= args.seeds; ++seed)
      for (const auto& [name, graph, sets] :
           {std::tuple{"A", args.graph_a, sets_a}, std::tuple{"B", args.graph_b, sets_b}})
        jobs.push_back({run_args(graph, sets, seed, args.duration, dir / "runs" / fmt::format("{}_seed{}", name, seed)),
                        dir / "runs" / fmt::format("{}_seed{}", name, seed)});
    const auto results = run_batch(jobs, jobs_or_cores(args.jobs));

    // Paired by seed: the same scenario and noise for both graphs.
    std::map<std::string, std::vector<std::pair<double, double>>> pairs;
    std::map<std::string, std::vector<int>> pair_seeds;  // the seed of each pair, for the plot
    std::size_t failed = 0;
    for (int s = 0; s < args.seeds; ++s) {
      const auto& a = results[static_cast<std::size_t>(2 * s)];
      const auto& b = results[static_cast<std::size_t>(2 * s + 1)];
      if (a.exit_code != 0 || b.exit_code != 0) {
        ++failed;
        continue;
      }
      const auto ma = report_metrics(a.report), mb = report_metrics(b.report);
      for (const auto& [k, va] : ma)
        if (auto it = mb.find(k); it != mb.end()) {
          pairs[k].emplace_back(va, it->second);
          pair_seeds[k].push_back(s + 1);
        }
    }
    nlohmann::json json = {{"a", args.graph_a},         {"b", args.graph_b},
                           {"set", args.overrides},     {"set_a", args.overrides_a},
                           {"set_b", args.overrides_b}, {"seeds", args.seeds},
                           {"failed_seeds", failed},    {"metrics", nlohmann::json::object()}};
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
    for (const auto& [metric, values] : pairs) {
      const int direction = better_direction(metric);
      if (direction == 0 || !headline(metric)) continue;
      const double n = static_cast<double>(values.size());
      double ma = 0, mb = 0, md_ = 0;
      for (const auto& [a, b] : values) {
        ma += a;
        mb += b;
        md_ += b - a;
      }
      ma /= n;
      mb /= n;
      md_ /= n;
      double var = 0;
      for (const auto& [a, b] : values) var += (b - a - md_) * (b - a - md_);
      const double sd = values.size() > 1 ? std::sqrt(var / (n - 1)) : 0.0;
      const double half = t_quantile_975(static_cast<int>(values.size()) - 1) * sd / std::sqrt(n);
      const double lo = md_ - half, hi = md_ + half;
      std::string better = "no significant difference";
      if (lo > 0 || hi < 0) better = (md_ > 0) == (direction > 0) ? "B" : "A";
      if (sd == 0 && md_ == 0) better = "equal";
      json["metrics"][metric] = {
          {"mean_a", ma}, {"mean_b", mb}, {"difference", md_}, {"ci95", {lo, hi}}, {"better", better}};
      md += fmt::format("| {} | {:.4g} | {:.4g} | {:+.4g} | [{:+.4g}, {:+.4g}] | {} |\n", metric, ma, mb, md_, lo, hi,
                        better);
      if (better != "equal" && panels.size() < 4) {
        plot::Panel panel{fmt::format("{} per seed (better: {})", metric, better), "seed", metric, {}};
        for (const auto& [name, side] : {std::pair{"A", 0}, std::pair{"B", 1}}) {
          plot::Series series{name, {}, {}, plot::Series::Style::points, plot::palette(side), 3};
          for (std::size_t i = 0; i < values.size(); ++i) {
            series.x.push_back(pair_seeds[metric][i]);
            series.y.push_back(side == 0 ? values[i].first : values[i].second);
          }
          panel.series.push_back(series);
        }
        panels.push_back(panel);
      }
    }
    if (failed) md += fmt::format("\n{} seed(s) left out: a run failed (see runs/*/run.log).\n", failed);
    std::filesystem::create_directories(dir);
    if (!panels.empty()) {
      plot::save_png(dir / "ab.png", panels, 900, 260);
      md += "\n![A and B seed by seed](ab.png)\n";
    }
    write(dir / "ab.md", md);
    write(dir / "ab.json", json.dump(2) + "\n");
    std::fputs(md.c_str(), stdout);
    return failed ? kRunFailed : kOk;
  } catch (const Error& e) {
    std::fprintf(stderr, "kestrel ab: %s\n", e.what());
    return kUsage;
  }
}

}  // namespace kestrel::cli
