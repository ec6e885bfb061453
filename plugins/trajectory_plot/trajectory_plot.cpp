// The `trajectory_plot` node: records ground truth, detections and tracks over a run and draws
// them against time, one panel per axis, as PNG (plus the samples as CSV).
#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <kestrel/messages/detections.hpp>
#include <kestrel/messages/ground_truth.hpp>
#include <kestrel/messages/tracks.hpp>
#include <kestrel/plot/line_plot.hpp>
#include <kestrel/plugin.hpp>
#include <map>
#include <sstream>

namespace kestrel::trajectory_plot {

class TrajectoryPlot final : public Node {
 public:
  static constexpr Input<msg::GroundTruth> kTruth{"truth"};
  static constexpr Input<msg::Detections> kDetections{"detections"};
  static constexpr Input<msg::Tracks> kTracks{"tracks"};

  static NodeSpec spec() {
    return NodeSpec("trajectory_plot", "Plots truth, detections and the selected track against time (PNG and CSV)")
        .details(
            "Camera-frame x, y and z against time, one panel each, like the paper's Figure 5. Files go to "
            "output_dir, or to the report folder (kestrel run --report DIR) when output_dir is empty.")
        .input(kTruth, "ground truth (camera frame is plotted)", {.optional = true})
        .input(kDetections, "detections (camera frame)", {.optional = true})
        .input(kTracks, "tracks; the selected one is plotted", {.optional = true})
        .param(param("name", std::string("trajectory")).describe("file names: NAME.png and NAME.csv"))
        .param(param("output_dir", std::string("")).describe("folder for the files; empty = the report folder"))
        .param(param("max_samples", 200000).at_least(1).describe("samples kept per series (memory bound)"))
        .param(param("from_s", 0.0).with_unit("s").at_least(0.0).describe("plot only from this time on"))
        .param(param("to_s", 0.0).with_unit("s").at_least(0.0).describe("plot only up to this time; 0 = the end"));
  }

  explicit TrajectoryPlot(NodeInit& init)
      : name_(init.param<std::string>("name")),
        output_dir_(init.param<std::string>("output_dir")),
        max_samples_(static_cast<std::size_t>(init.param<std::int64_t>("max_samples"))),
        from_(init.param<double>("from_s")),
        to_(init.param<double>("to_s")) {}

  void process(Context& ctx) override {
    if (ctx.triggered_by(kTruth)) {
      const auto truth = ctx.get(kTruth);
      for (const auto& o : truth->objects) add("truth " + std::to_string(o.id), truth->stamp, o.position_camera);
    } else if (ctx.triggered_by(kDetections)) {
      const auto detections = ctx.get(kDetections);
      for (const auto& d : detections->items) add("detections", detections->stamp, d.position);
    } else if (ctx.triggered_by(kTracks)) {
      const auto tracks = ctx.get(kTracks);
      if (const auto* t = tracks->selected()) add("selected track", tracks->stamp, t->position());
    }
  }

  void finish(Context& ctx) override {
    if (output_dir_.empty() && !ctx.keeps_artifacts()) {
      ctx.log().info("no output folder: run with --report DIR (or set output_dir) to get {}.png", name_);
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
          if (s.t[i] < from_ || (to_ > 0 && s.t[i] > to_)) continue;
          line.x.push_back(s.t[i]);
          line.y.push_back(s.p[i][a]);
        }
        panels[static_cast<std::size_t>(a)].series.push_back(std::move(line));
      }
    }
    const std::string png = plot::render_png(panels);
    if (output_dir_.empty()) {
      ctx.add_artifact(name_ + ".csv", csv(), "truth, detections and selected track against time");
      ctx.add_artifact(name_ + ".png", png, "truth, detections and selected track against time (camera frame)");
      return;
    }
    const std::filesystem::path dir(output_dir_);
    std::filesystem::create_directories(dir);
    write_file(dir / (name_ + ".csv"), csv());
    write_file(dir / (name_ + ".png"), png);
    ctx.log().info("wrote {}", (dir / (name_ + ".png")).string());
  }

 private:
  struct Samples {
    std::vector<double> t;
    std::vector<Eigen::Vector3d> p;
  };

  void add(const std::string& label, Time stamp, const Eigen::Vector3d& p) {
    Samples& s = series_[label];
    if (s.t.size() >= max_samples_) return;
    s.t.push_back(to_seconds(stamp));
    s.p.push_back(p);
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

  static void write_file(const std::filesystem::path& file, const std::string& bytes) {
    std::ofstream out(file, std::ios::binary);
    out << bytes;
    out.close();
    if (!out) throw Error("cannot write " + file.string());
  }

  std::string name_;
  std::string output_dir_;
  std::size_t max_samples_;
  double from_, to_;
  std::map<std::string, Samples> series_;
};
KESTREL_REGISTER_NODE(TrajectoryPlot)

}  // namespace kestrel::trajectory_plot
