// The `trajectory_plot` node: records ground truth, detections and tracks over a run and draws
// them against time, one panel per axis, as PNG (plus the samples as CSV), into the run report.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <kestrel/messages/detections.hpp>
#include <kestrel/messages/ground_truth.hpp>
#include <kestrel/messages/tracks.hpp>
#include <kestrel/plot/line_plot.hpp>
#include <kestrel/plugin.hpp>
#include <map>
#include <sstream>

namespace kestrel::trajectory_plot {

struct TrajectoryPlotConfig {
  std::string name = "trajectory";
  std::int64_t max_samples = 200000;
  double from_s = 0.0;
  double to_s = 0.0;
};

class TrajectoryPlot final : public Node {
 public:
  static constexpr Input<msg::GroundTruth> kTruth{"truth"};
  static constexpr Input<msg::Detections> kDetections{"detections"};
  static constexpr Input<msg::Tracks> kTracks{"tracks"};

  static NodeSpec spec() {
    using C = TrajectoryPlotConfig;
    ConfigSpec<C> c;
    c.param("name", &C::name).describe("file names in the report folder: NAME.png and NAME.csv");
    c.param("max_samples", &C::max_samples)
        .at_least(1)
        .describe("samples kept per series (memory bound); later ones are counted in the report, not kept");
    c.param("from_s", &C::from_s).with_unit("s").at_least(0.0).describe("plot only from this time on");
    c.param("to_s", &C::to_s).with_unit("s").at_least(0.0).describe("plot only up to this time; 0 = the end");
    c.rule("name is a plain file name (not empty, no '/', no leading '.')", {"name"}, [](const C& k) {
      return !k.name.empty() && k.name.find('/') == std::string::npos && k.name.front() != '.';
    });
    c.rule("from_s < to_s (unless to_s = 0: the end)", {"from_s", "to_s"},
           [](const C& k) { return k.to_s == 0.0 || k.from_s < k.to_s; });
    return NodeSpec("trajectory_plot", "Plots truth, detections and the selected track against time (PNG and CSV)")
        .details(
            "Camera-frame x, y and z against time, one panel each, like the paper's Figure 5, added to the run "
            "report (kestrel run --report DIR) as NAME.png and NAME.csv. Each series keeps at most max_samples "
            "samples; the report section under this node's id counts the samples kept and those dropped.")
        .input(kTruth, "ground truth (camera frame is plotted)", {.optional = true})
        .input(kDetections, "detections (camera frame)", {.optional = true})
        .input(kTracks, "tracks; the selected one is plotted", {.optional = true})
        .config(std::move(c));
  }

  explicit TrajectoryPlot(NodeInit& init) : cfg_(init.config<TrajectoryPlotConfig>()) {}

  void process(Context& ctx) override {
    if (ctx.triggered_by(kTruth)) {
      const auto truth = ctx.get(kTruth);
      for (const auto& o : truth->objects) add(ctx, "truth " + std::to_string(o.id), truth->stamp, o.position_camera);
    } else if (ctx.triggered_by(kDetections)) {
      const auto detections = ctx.get(kDetections);
      for (const auto& d : detections->items) add(ctx, "detections", detections->stamp, d.position);
    } else if (ctx.triggered_by(kTracks)) {
      const auto tracks = ctx.get(kTracks);
      if (const auto* t = tracks->selected()) add(ctx, "selected track", tracks->stamp, t->position());
    }
  }

  void finish(Context& ctx) override {
    report_counts(ctx);
    if (!ctx.keeps_artifacts()) {
      ctx.log().info("no report folder: run with --report DIR to get {}.png", cfg_.name);
      return;
    }
    std::vector<plot::Panel> panels(3);
    const char* axes[] = {"x", "y", "z"};
    for (int a = 0; a < 3; ++a) {
      panels[static_cast<std::size_t>(a)].title = std::string("camera-frame ") + axes[a];
      panels[static_cast<std::size_t>(a)].x_label = "time [s]";
      panels[static_cast<std::size_t>(a)].y_label = std::string(axes[a]) + " [m]";
      std::size_t colour = 0;
      for (const auto& [label, s] : series_) {
        plot::Series line;
        line.label = label;
        line.color = plot::palette(colour++);
        line.style = label == "detections" ? plot::Series::Style::points : plot::Series::Style::line;
        line.thickness = label == "detections" ? 1 : 2;
        for (std::size_t i = 0; i < s.t.size(); ++i) {
          if (s.t[i] < cfg_.from_s || (cfg_.to_s > 0 && s.t[i] > cfg_.to_s)) continue;
          line.x.push_back(s.t[i]);
          line.y.push_back(s.p[i][a]);
        }
        panels[static_cast<std::size_t>(a)].series.push_back(std::move(line));
      }
    }
    const std::string cut = dropped_total() > 0 ? fmt::format(" ({} later samples dropped)", dropped_total()) : "";
    ctx.add_artifact(cfg_.name + ".csv", csv(), "truth, detections and selected track against time" + cut);
    ctx.add_artifact(cfg_.name + ".png", plot::render_png(panels),
                     "truth, detections and selected track against time (camera frame)" + cut);
  }

 private:
  struct Samples {
    std::vector<double> t;
    std::vector<Eigen::Vector3d> p;
    std::uint64_t dropped = 0;  // beyond max_samples
  };

  void add(Context& ctx, const std::string& label, Time stamp, const Eigen::Vector3d& p) {
    Samples& s = series_[label];
    if (s.t.size() >= static_cast<std::size_t>(cfg_.max_samples)) {
      if (s.dropped++ == 0)
        ctx.log().warn("series '{}' reached max_samples ({}); later samples are counted in the report, not kept", label,
                       cfg_.max_samples);
      return;
    }
    s.t.push_back(to_seconds(stamp));
    s.p.push_back(p);
  }

  std::uint64_t dropped_total() const {
    std::uint64_t n = 0;
    for (const auto& [label, s] : series_) n += s.dropped;
    return n;
  }

  // Samples kept and dropped, per series and in total, under this node's id.
  void report_counts(Context& ctx) const {
    nlohmann::json series = nlohmann::json::object();
    std::uint64_t kept = 0;
    std::vector<std::string> cut;  // report.md names the series that lost samples
    for (const auto& [label, s] : series_) {
      series[label] = {{"samples", s.t.size()}, {"dropped_samples", s.dropped}};
      kept += s.t.size();
      if (s.dropped > 0) cut.push_back(fmt::format("{} ({})", label, s.dropped));
    }
    const std::uint64_t dropped = dropped_total();
    std::string md = fmt::format("{} samples plotted as {}.png", kept, cfg_.name);
    md += dropped > 0 ? fmt::format("; {} later samples dropped beyond max_samples = {} per series: {}.\n", dropped,
                                    cfg_.max_samples, fmt::join(cut, ", "))
                      : ", none dropped.\n";
    ctx.set_report_section(ctx.id(), ReportSection()
                                         .quantity("samples", kept)
                                         .metric("dropped_samples", dropped, "", Better::lower)
                                         .quantity("series", series)
                                         .markdown(md));
  }

  std::string csv() const {
    std::ostringstream out;
    out << "series,t,x,y,z\n";
    for (const auto& [label, s] : series_)
      for (std::size_t i = 0; i < s.t.size(); ++i)
        // Shortest text that reads back as the same double: the CSV holds exactly what was plotted.
        out << fmt::format("{},{},{},{},{}\n", label, s.t[i], s.p[i].x(), s.p[i].y(), s.p[i].z());
    return out.str();
  }

  TrajectoryPlotConfig cfg_;
  std::map<std::string, Samples> series_;
};
KESTREL_REGISTER_NODE(TrajectoryPlot)

}  // namespace kestrel::trajectory_plot
