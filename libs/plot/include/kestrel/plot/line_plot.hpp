#pragma once
// Line and scatter plots written as PNG, for reports: trajectories against time, metrics
// against a parameter. Drawn with OpenCV so that any node or tool can make one without Python.
#include <filesystem>
#include <string>
#include <vector>

namespace kestrel::plot {

struct Color {
  unsigned char r = 0, g = 0, b = 0;
};

/// A few distinct colours (Tableau 10), used in order when a series gives none.
Color palette(std::size_t index);

struct Series {
  std::string label;
  std::vector<double> x;
  std::vector<double> y;
  enum class Style { line, points, line_and_points } style = Style::line;
  Color color = palette(0);
  int thickness = 2;
};

/// One panel: axes with a title, labels and any number of series. Ranges are automatic unless
/// set.
struct Panel {
  std::string title;
  std::string x_label;
  std::string y_label;
  std::vector<Series> series;
  bool has_y_range = false;
  double y_min = 0.0, y_max = 1.0;
};

/// The panels stacked vertically, as the bytes of one PNG image (for Context::add_artifact).
std::string render_png(const std::vector<Panel>& panels, int width = 1000, int panel_height = 300);

/// Writes the panels stacked vertically into one PNG. Throws kestrel::Error if it cannot write.
void save_png(const std::filesystem::path& file, const std::vector<Panel>& panels, int width = 1000,
              int panel_height = 300);

/// "Nice" tick positions (1, 2 or 5 times a power of ten) covering [lo, hi].
std::vector<double> nice_ticks(double lo, double hi, int target_count = 6);

}  // namespace kestrel::plot
