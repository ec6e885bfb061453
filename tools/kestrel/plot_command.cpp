// kestrel plot CSV --x COL --y COL[+COL][,COL...] -o PNG [--meta JSON]: a quick PNG of columns
// of a CSV file (sweep tables, per-frame errors), one panel per y entry; COL+COL overlays columns
// in a panel. Units and which way is better come from a metrics_meta (kestrel sweep writes
// metrics_meta.json beside sweep.csv).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "command_errors.hpp"
#include "commands.hpp"
#include "csv_format.hpp"
#include "kestrel/error.hpp"
#include "kestrel/plot/line_plot.hpp"
#include "metrics_meta.hpp"
#include "output_files.hpp"

namespace kestrel::cli {

namespace {

// --meta, or else metrics_meta.json beside the CSV if there is one; nothing otherwise.
MetricsMeta read_meta(const PlotArgs& args) {
  MetricsMeta meta;
  std::filesystem::path file = args.meta;
  if (file.empty()) {
    file = std::filesystem::path(args.csv).parent_path() / "metrics_meta.json";
    if (!std::filesystem::exists(file)) return meta;
  }
  std::ifstream in(file);
  if (!in) throw Error("cannot open " + file.string());
  const nlohmann::json json = nlohmann::json::parse(in, nullptr, false);
  if (!json.is_object() || !json.contains("metrics_meta"))
    throw Error(file.string() + ": expected a JSON object with \"metrics_meta\" (a report.json, or metrics_meta.json)");
  meta.add(json);
  return meta;
}

// The unit that every column of an overlay shares, as an axis label; "" if they differ.
std::string shared_unit(const std::vector<std::string>& columns, const MetricsMeta& meta) {
  std::string unit;
  for (const auto& c : columns) {
    const MetricMeta* m = meta.find(c);
    if (!m || m->unit.empty() || (!unit.empty() && unit != m->unit)) return "";
    unit = m->unit;
  }
  return "[" + unit + "]";
}

}  // namespace

int plot_command(const PlotArgs& args) {
  return run_command_body("plot", [&] {
    std::ifstream in(args.csv);
    if (!in) throw Error("cannot open " + args.csv);
    const std::vector<CsvRecord> records = read_csv(in, args.csv);
    if (records.empty()) throw Error(args.csv + " is empty: expected a header row");
    const std::vector<std::string>& header = records.front().cells;
    auto column = [&](const std::string& name) {
      for (std::size_t i = 0; i < header.size(); ++i)
        if (header[i] == name) return i;
      throw Error("no column '" + name + "' in " + args.csv);
    };
    const std::size_t x = column(args.x);
    const MetricsMeta meta = read_meta(args);
    // One panel per --y entry; "a+b" overlays columns a and b in one panel.
    std::vector<plot::Panel> panels;
    std::vector<std::vector<std::size_t>> panel_columns;
    std::size_t colour = 0;
    for (const auto& entry : args.y) {
      plot::Panel panel;
      std::vector<std::size_t> columns;
      std::vector<std::string> column_names;
      std::stringstream names(entry);
      for (std::string name; std::getline(names, name, '+');) {
        columns.push_back(column(name));
        column_names.push_back(name);
        plot::Series s;
        s.label = name;
        s.color = plot::palette(colour++);
        s.style = plot::Series::Style::line_and_points;
        panel.series.push_back(s);
      }
      const std::string better = column_names.size() == 1 ? meta.better_text(entry) : "";
      panel.title = entry + " against " + args.x + (better.empty() ? "" : " (" + better + ")");
      panel.x_label = meta.label(args.x);
      panel.y_label = column_names.size() == 1 ? meta.label(entry) : shared_unit(column_names, meta);
      panels.push_back(panel);
      panel_columns.push_back(columns);
    }
    for (std::size_t r = 1; r < records.size(); ++r) {
      const std::vector<std::string>& cells = records[r].cells;
      // An empty cell is a gap in its curve; anything else must be a number.
      auto value = [&](std::size_t i) {
        if (i >= cells.size() || cells[i].empty()) return std::numeric_limits<double>::quiet_NaN();
        try {
          std::size_t used = 0;
          const double v = std::stod(cells[i], &used);
          if (used == cells[i].size()) return v;
        } catch (const std::exception&) {
        }
        throw Error(SourceLocation{args.csv, records[r].line, 0},
                    "column " + header[i] + " is not a number: '" + cells[i] + "'");
      };
      for (std::size_t p = 0; p < panels.size(); ++p)
        for (std::size_t c = 0; c < panel_columns[p].size(); ++c) {
          panels[p].series[c].x.push_back(value(x));
          panels[p].series[c].y.push_back(value(panel_columns[p][c]));
        }
    }
    write_png(args.output, panels, 900, 320);
    std::printf("wrote %s\n", args.output.c_str());
    // Undefined values (empty cells, as sweep.csv writes a null metric) are gaps: say how many.
    for (const auto& panel : panels)
      for (const auto& series : panel.series) {
        const auto gaps = std::count_if(series.y.begin(), series.y.end(), [](double v) { return std::isnan(v); });
        if (gaps > 0)
          std::printf("%s: %ld of %zu rows undefined (empty cells), drawn as gaps\n", series.label.c_str(),
                      static_cast<long>(gaps), series.y.size());
      }
    return kOk;
  });
}

}  // namespace kestrel::cli
