// kestrel plot CSV --x COL --y COL[+COL][,COL...] -o PNG: a quick PNG of columns of a CSV file
// (sweep tables, per-frame errors), one panel per y entry; COL+COL overlays columns in a panel.
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>

#include "command_errors.hpp"
#include "commands.hpp"
#include "kestrel/error.hpp"
#include "kestrel/plot/line_plot.hpp"
#include "output_files.hpp"

namespace kestrel::cli {

int plot_command(const PlotArgs& args) {
  return run_command_body("plot", [&] {
    std::ifstream in(args.csv);
    if (!in) throw Error("cannot open " + args.csv);
    std::string line;
    std::getline(in, line);
    std::vector<std::string> header;
    {
      std::stringstream cells(line);
      for (std::string cell; std::getline(cells, cell, ',');) header.push_back(cell);
    }
    auto column = [&](const std::string& name) {
      for (std::size_t i = 0; i < header.size(); ++i)
        if (header[i] == name) return i;
      throw Error("no column '" + name + "' in " + args.csv);
    };
    const std::size_t x = column(args.x);
    // One panel per --y entry; "a+b" overlays columns a and b in one panel.
    std::vector<plot::Panel> panels;
    std::vector<std::vector<std::size_t>> panel_columns;
    std::size_t colour = 0;
    for (const auto& entry : args.y) {
      plot::Panel panel;
      std::vector<std::size_t> columns;
      std::stringstream names(entry);
      for (std::string name; std::getline(names, name, '+');) {
        columns.push_back(column(name));
        plot::Series s;
        s.label = name;
        s.color = plot::palette(colour++);
        s.style = plot::Series::Style::line_and_points;
        panel.series.push_back(s);
      }
      panel.title = entry + " against " + args.x;
      panel.x_label = args.x;
      panel.y_label = panel.series.size() == 1 ? entry : "";
      panels.push_back(panel);
      panel_columns.push_back(columns);
    }
    int number = 1;
    while (std::getline(in, line)) {
      ++number;
      if (line.empty()) continue;
      std::vector<std::string> cells;
      std::stringstream stream(line);
      for (std::string cell; std::getline(stream, cell, ',');) cells.push_back(cell);
      // An empty cell is a gap in its curve; anything else must be a number.
      auto value = [&](std::size_t i) {
        if (i >= cells.size() || cells[i].empty()) return std::numeric_limits<double>::quiet_NaN();
        try {
          std::size_t used = 0;
          const double v = std::stod(cells[i], &used);
          if (used == cells[i].size()) return v;
        } catch (const std::exception&) {
        }
        throw Error(SourceLocation{args.csv, number, 0},
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
    return kOk;
  });
}

}  // namespace kestrel::cli
