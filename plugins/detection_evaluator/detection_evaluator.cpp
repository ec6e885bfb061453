// The `detection_evaluator` node: precision, recall, per-axis RMSE and lag of detections against
// the simulator's ground truth, added to report.json as "detection".
#include <fmt/format.h>

#include <kestrel/evaluation/scoring_params.hpp>
#include <kestrel/evaluation/truth_pairing.hpp>
#include <kestrel/messages/detections.hpp>
#include <kestrel/messages/ground_truth.hpp>
#include <kestrel/plugin.hpp>
#include <map>

#include "detection_report.hpp"
#include "detection_scoring.hpp"

namespace kestrel::evaluation {

class DetectionEvaluator final : public Node {
 public:
  static constexpr Input<msg::Detections> kDetections{"detections"};
  static constexpr Input<msg::GroundTruth> kTruth{"truth"};

  struct Config {
    ScoringParams scoring{.section = "detection"};
  };

  static NodeSpec spec() {
    ConfigSpec<Config> c;
    declare_scoring_params(c, &Config::scoring,
                           "largest error still matched (paper: 1.0 m, its maximum reconstruction error)");
    return NodeSpec("detection_evaluator", "Precision, recall, RMSE and lag of detections against ground truth")
        .details(
            "Each frame's detections are matched to the truth of the same capture time by Hungarian assignment "
            "of Euclidean distances; pairs farther than match_radius_m are never matched. Unmatched detections "
            "are false positives; unmatched truth objects in view are misses. RMSE is per camera axis over "
            "matched detections. The lag is the shift maximising the cross-correlation between the true curve "
            "(at capture times) and the detected one (at the times detections reached this node): zero under "
            "lockstep, the processing delay under realtime. A figure with nothing to measure it on (precision "
            "without detections, RMSE without matches) is null in report.json and \"undefined\" in report.md. "
            "Adds \"detection\" to report.json, and with --report the matches and per-frame counts as "
            "detection.csv and detection_per_frame.csv.")
        .input(kDetections, "detections to score")
        .input(kTruth, "ground truth at each capture time")
        .config(std::move(c));
  }

  explicit DetectionEvaluator(NodeInit& init) : DetectionEvaluator(init.config<Config>().scoring) {}
  explicit DetectionEvaluator(const ScoringParams& p)
      : scorer_(p.match_radius_m, p.skip_first_s),
        max_lag_(p.max_lag_s),
        lag_step_(p.lag_step_s),
        section_(p.section) {}

  void process(Context& ctx) override {
    if (ctx.triggered_by(kTruth)) {
      pairing_.add_truth(ctx.get(kTruth));
    } else {
      const auto detections = ctx.get(kDetections);
      pairing_.add(detections->stamp, detections, to_seconds(ctx.now()));
    }
    pairing_.pair(
        [this](const msg::Detections& d, const msg::GroundTruth& t, double arrival) { score(d, t, arrival); });
  }

  void finish(Context& ctx) override {
    if (pairing_.unpaired_items() > 0)
      ctx.log().warn("{} detection message(s) had no ground truth with their capture time; not scored",
                     pairing_.unpaired_items());
    ReportSection section = detection_report(scorer_.summary(max_lag_, lag_step_));
    add_unpaired(section, pairing_.unpaired_items(), pairing_.unpaired_truths());
    ctx.set_report_section(section_, section);
    if (ctx.keeps_artifacts()) {
      ctx.add_artifact(section_ + ".csv", matches_csv(), "matched detections with their errors");
      ctx.add_artifact(section_ + "_per_frame.csv", counts_csv(), "TP, FP and FN per frame");
    }
  }

 private:
  void score(const msg::Detections& detections, const msg::GroundTruth& truth, double arrival_s) {
    std::vector<Eigen::Vector3d> found;
    for (const auto& d : detections.items) found.push_back(d.position);
    std::vector<TruthObject> objects;
    for (const auto& o : truth.objects) objects.push_back({o.id, o.position_camera, o.in_view});
    const FrameScore frame = scorer_.add_frame(to_seconds(truth.stamp), arrival_s, found, objects);
    if (!frame.scored) return;  // before skip_first_s
    for (const auto& m : frame.matches)
      rows_.push_back(
          fmt::format("{:.4f},{:.4f},{},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f}", frame.capture_s, arrival_s,
                      objects[static_cast<std::size_t>(m.truth)].id, found[static_cast<std::size_t>(m.detection)].x(),
                      found[static_cast<std::size_t>(m.detection)].y(),
                      found[static_cast<std::size_t>(m.detection)].z(), m.error.x(), m.error.y(), m.error.z()));
    frames_.push_back(fmt::format("{:.4f},{},{},{}", frame.capture_s, frame.tp, frame.fp, frame.fn));
  }

  std::string matches_csv() const {
    std::string csv = "capture_s,arrival_s,truth_id,x,y,z,error_x,error_y,error_z\n";
    for (const auto& r : rows_) csv += r + '\n';
    return csv;
  }
  std::string counts_csv() const {
    std::string csv = "capture_s,tp,fp,fn\n";
    for (const auto& r : frames_) csv += r + '\n';
    return csv;
  }

  DetectionScorer scorer_;
  double max_lag_, lag_step_;
  std::string section_;
  TruthPairing<msg::Detections> pairing_;
  std::vector<std::string> rows_;
  std::vector<std::string> frames_;
};
KESTREL_REGISTER_NODE(DetectionEvaluator)

}  // namespace kestrel::evaluation
