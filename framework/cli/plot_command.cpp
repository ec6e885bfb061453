// kestrel plot CSV --x COL --y COL[,COL...] -o PNG: a quick PNG of columns of a CSV file (sweep
// tables, per-frame errors), one panel per y column.
#include <cstdio>
#include <fstream>
#include <sstream>

#include "commands.hpp"
#include "kestrel/error.hpp"
#include "kestrel/plot/line_plot.hpp"

namespace kestrel::cli {

int plot_command(const PlotArgs& args) {
  try {
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
    std::vector<std::size_t> ys;
    for (const auto& y : args.y) ys.push_back(column(y));

    std::vector<plot::Panel> panels(ys.size());
    for (std::size_t p = 0; p < ys.size(); ++p) {
      panels[p].title = args.y[p] + " against " + args.x;
      panels[p].x_label = args.x;
      panels[p].y_label = args.y[p];
      plot::Series s;
      s.label = args.y[p];
      s.color = plot::palette(p);
      s.style = plot::Series::Style::line_and_points;
      panels[p].series.push_back(s);
    }
    int number = 1;
    while (std::getline(in, line)) {
      ++number;
      if (line.empty()) continue;
      std::vector<std::string> cells;
      std::stringstream stream(line);
      for (std::string cell; std::getline(stream, cell, ',');) cells.push_back(cell);
      auto value = [&](std::size_t i) {
        try {
          return std::stod(cells.at(i));
        } catch (const std::exception&) {
          throw Error(SourceLocation{args.csv, number, 0}, "column " + header[i] + " is not a number");
        }
      };
      for (std::size_t p = 0; p < ys.size(); ++p) {
        panels[p].series[0].x.push_back(value(x));
        panels[p].series[0].y.push_back(value(ys[p]));
      }
    }
    plot::save_png(args.output, panels, 900, 320);
    std::printf("wrote %s\n", args.output.c_str());
    return kOk;
  } catch (const Error& e) {
    std::fprintf(stderr, "kestrel plot: %s\n", e.what());
    return kUsage;
  }
}

}  // namespace kestrel::cli
