#include "kestrel/plot/line_plot.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "kestrel/error.hpp"

namespace kestrel::plot {

namespace {

cv::Scalar bgr(Color c) { return cv::Scalar(c.b, c.g, c.r); }

const cv::Scalar kInk(40, 40, 40);
const cv::Scalar kGrid(225, 225, 225);
constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;

struct Range {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  void add(double v) {
    if (!std::isfinite(v)) return;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  void finish() {
    if (!std::isfinite(lo)) lo = 0.0, hi = 1.0;
    if (hi - lo < 1e-12) lo -= 0.5, hi += 0.5;
    const double pad = 0.05 * (hi - lo);
    lo -= pad;
    hi += pad;
  }
};

std::string tick_label(double v, double step) {
  const int decimals = step >= 1.0 ? 0 : static_cast<int>(std::ceil(-std::log10(step)));
  return fmt::format("{:.{}f}", std::abs(v) < step * 1e-6 ? 0.0 : v, decimals);
}

void put_text(cv::Mat& img, const std::string& text, cv::Point at, double scale, cv::Scalar color, bool centred = false,
              bool right = false) {
  int baseline = 0;
  const cv::Size size = cv::getTextSize(text, kFont, scale, 1, &baseline);
  if (centred) at.x -= size.width / 2;
  if (right) at.x -= size.width;
  cv::putText(img, text, at, kFont, scale, color, 1, cv::LINE_AA);
}

void draw_panel(cv::Mat& img, const Panel& panel, cv::Rect area) {
  const int left = 80, right = 20, top = 30, bottom = 45;
  const cv::Rect plot(area.x + left, area.y + top, area.width - left - right, area.height - top - bottom);

  Range xr, yr;
  for (const auto& s : panel.series) {
    for (double v : s.x) xr.add(v);
    for (double v : s.y) yr.add(v);
  }
  xr.finish();
  if (panel.has_y_range) {
    yr.lo = panel.y_min;
    yr.hi = panel.y_max;
  } else {
    yr.finish();
  }
  auto px = [&](double x) { return plot.x + (x - xr.lo) / (xr.hi - xr.lo) * plot.width; };
  auto py = [&](double y) { return plot.y + plot.height - (y - yr.lo) / (yr.hi - yr.lo) * plot.height; };

  const auto xt = nice_ticks(xr.lo, xr.hi);
  const auto yt = nice_ticks(yr.lo, yr.hi);
  for (double x : xt) {
    const int X = static_cast<int>(std::lround(px(x)));
    cv::line(img, {X, plot.y}, {X, plot.y + plot.height}, kGrid, 1);
    put_text(img, tick_label(x, xt.size() > 1 ? xt[1] - xt[0] : 1.0), {X, plot.y + plot.height + 18}, 0.45, kInk, true);
  }
  for (double y : yt) {
    const int Y = static_cast<int>(std::lround(py(y)));
    cv::line(img, {plot.x, Y}, {plot.x + plot.width, Y}, kGrid, 1);
    put_text(img, tick_label(y, yt.size() > 1 ? yt[1] - yt[0] : 1.0), {plot.x - 6, Y + 5}, 0.45, kInk, false, true);
  }
  cv::rectangle(img, plot, kInk, 1);
  put_text(img, panel.title, {plot.x + plot.width / 2, area.y + 20}, 0.6, kInk, true);
  put_text(img, panel.x_label, {plot.x + plot.width / 2, area.y + area.height - 8}, 0.5, kInk, true);
  if (!panel.y_label.empty()) {
    // Rotated y label: draw horizontally into a strip, rotate, copy beside the axis.
    int baseline = 0;
    const cv::Size size = cv::getTextSize(panel.y_label, kFont, 0.5, 1, &baseline);
    cv::Mat strip(size.height + 8, size.width + 4, CV_8UC3, cv::Scalar(255, 255, 255));
    cv::putText(strip, panel.y_label, {2, size.height + 2}, kFont, 0.5, kInk, 1, cv::LINE_AA);
    cv::Mat rotated;
    cv::rotate(strip, rotated, cv::ROTATE_90_COUNTERCLOCKWISE);
    const int x0 = area.x + 4;
    const int y0 = std::max(area.y, plot.y + plot.height / 2 - rotated.rows / 2);
    const cv::Rect target(x0, y0, rotated.cols, std::min(rotated.rows, img.rows - y0));
    rotated(cv::Rect(0, 0, target.width, target.height)).copyTo(img(target));
  }

  cv::Mat clip = img(plot);
  for (std::size_t i = 0; i < panel.series.size(); ++i) {
    const Series& s = panel.series[i];
    const cv::Scalar color = bgr(s.color);
    std::vector<cv::Point> run;
    auto flush = [&] {
      if (run.size() > 1) cv::polylines(clip, run, false, color, s.thickness, cv::LINE_AA);
      run.clear();
    };
    const std::size_t n = std::min(s.x.size(), s.y.size());
    for (std::size_t k = 0; k < n; ++k) {
      if (!std::isfinite(s.x[k]) || !std::isfinite(s.y[k])) {
        flush();  // a gap: NaN breaks the line
        continue;
      }
      const cv::Point p(static_cast<int>(std::lround(px(s.x[k]) - plot.x)),
                        static_cast<int>(std::lround(py(s.y[k]) - plot.y)));
      if (s.style != Series::Style::points) run.push_back(p);
      if (s.style != Series::Style::line) cv::circle(clip, p, s.thickness + 1, color, cv::FILLED, cv::LINE_AA);
    }
    flush();
  }

  // Legend inside the plot, on white so curves do not hide it, in the corner that covers the
  // fewest data points (top right when there is a tie).
  int labelled = 0, text_width = 0;
  for (const auto& s : panel.series) {
    if (s.label.empty()) continue;
    ++labelled;
    int baseline = 0;
    text_width = std::max(text_width, cv::getTextSize(s.label, kFont, 0.45, 1, &baseline).width);
  }
  if (labelled == 0) return;
  const cv::Size box(std::min(plot.width - 8, text_width + 42), 18 * labelled + 6);
  const cv::Rect corners[] = {
      {plot.x + plot.width - box.width - 4, plot.y + 4, box.width, box.height},
      {plot.x + 4, plot.y + 4, box.width, box.height},
      {plot.x + plot.width - box.width - 4, plot.y + plot.height - box.height - 4, box.width, box.height},
      {plot.x + 4, plot.y + plot.height - box.height - 4, box.width, box.height}};
  auto covered = [&](const cv::Rect& r) {
    int n = 0;
    for (const auto& s : panel.series)
      for (std::size_t k = 0; k < std::min(s.x.size(), s.y.size()); ++k)
        if (std::isfinite(s.x[k]) && std::isfinite(s.y[k]) &&
            r.contains(cv::Point(static_cast<int>(std::lround(px(s.x[k]))), static_cast<int>(std::lround(py(s.y[k]))))))
          ++n;
    return n;
  };
  cv::Rect legend = corners[0];
  int least = covered(legend);
  for (const auto& r : corners)
    if (const int n = covered(r); n < least) {
      least = n;
      legend = r;
    }
  cv::rectangle(img, legend, cv::Scalar(255, 255, 255), cv::FILLED);
  int y = legend.y + 14;
  for (const auto& s : panel.series) {
    if (s.label.empty()) continue;
    const int x = legend.x + 6;
    cv::line(img, {x, y - 5}, {x + 24, y - 5}, bgr(s.color), 3, cv::LINE_AA);
    put_text(img, s.label, {x + 30, y}, 0.45, kInk);
    y += 18;
  }
}

}  // namespace

Color palette(std::size_t index) {
  static const Color colors[] = {{31, 119, 180}, {255, 127, 14},  {44, 160, 44},   {214, 39, 40},  {148, 103, 189},
                                 {140, 86, 75},  {227, 119, 194}, {127, 127, 127}, {188, 189, 34}, {23, 190, 207}};
  return colors[index % (sizeof colors / sizeof colors[0])];
}

std::vector<double> nice_ticks(double lo, double hi, int target_count) {
  std::vector<double> ticks;
  if (!(hi > lo) || target_count < 2) return ticks;
  const double raw = (hi - lo) / (target_count - 1);
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  double step = magnitude;
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    step = m * magnitude;
    if (step >= raw) break;
  }
  for (double t = std::ceil(lo / step) * step; t <= hi + step * 1e-9; t += step) ticks.push_back(t);
  return ticks;
}

namespace {
cv::Mat render(const std::vector<Panel>& panels, int width, int panel_height) {
  const int count = std::max<int>(1, static_cast<int>(panels.size()));
  cv::Mat img(panel_height * count, width, CV_8UC3, cv::Scalar(255, 255, 255));
  for (int i = 0; i < static_cast<int>(panels.size()); ++i)
    draw_panel(img, panels[static_cast<std::size_t>(i)], cv::Rect(0, i * panel_height, width, panel_height));
  return img;
}
}  // namespace

std::string render_png(const std::vector<Panel>& panels, int width, int panel_height) {
  std::vector<unsigned char> bytes;
  if (!cv::imencode(".png", render(panels, width, panel_height), bytes)) throw Error("cannot encode a plot as PNG");
  return {bytes.begin(), bytes.end()};
}

void save_png(const std::filesystem::path& file, const std::vector<Panel>& panels, int width, int panel_height) {
  // Encoded in memory, then written with every step checked: imwrite picks the format by the
  // name's extension and reports neither a full disk nor a failed close.
  const std::string png = render_png(panels, width, panel_height);
  std::FILE* out = std::fopen(file.c_str(), "wb");
  if (!out) throw Error("cannot write plot " + file.string() + ": " + std::strerror(errno));
  const bool written = std::fwrite(png.data(), 1, png.size(), out) == png.size();
  const int saved_errno = errno;
  if (std::fclose(out) != 0 || !written)
    throw Error("cannot write plot " + file.string() + ": " + std::strerror(written ? errno : saved_errno));
}

}  // namespace kestrel::plot
