// The `mot_evaluator` node: CLEAR-MOT (MOTA, MOTP, IDSW, fragmentations, MT/PT/ML), IDF1, the
// selected track's RMSE and the tracking lag, against the simulator's ground truth.
#include <fmt/format.h>
#include <kestrel/algorithms/clear_mot.hpp>
#include <kestrel/algorithms/lag.hpp>
#include <kestrel/evaluation/scoring_params.hpp>
#include <kestrel/evaluation/truth_pairing.hpp>
#include <kestrel/messages/ground_truth.hpp>
#include <kestrel/messages/tracks.hpp>
#include <kestrel/plugin.hpp>

#include <cmath>
#include <map>

namespace kestrel::evaluation {

class MotEvaluator final : public Node {
 public:
  static constexpr Input<msg::Tracks> kTracks{"tracks"};
  static constexpr Input<msg::GroundTruth> kTruth{"truth"};

  static NodeSpec spec() {
    NodeSpec spec = NodeSpec("mot_evaluator", "CLEAR-MOT and IDF1 of tracks against ground truth, and the target's RMSE and lag")
        .details("Each frame, tracks are paired with the truth of the same capture time. Correspondences from earlier "
                 "frames are kept while their distance stays within match_radius_m; the rest are assigned by the "
                 "Hungarian method; a ground-truth object matched to another track than before is an identity "
                 "switch (MOT16, py-motmetrics). Also the RMSE of the selected track against the truth object it "
                 "follows, and the tracking lag by cross-correlation. Adds \"tracking\" to report.json.")
        .input(kTracks, "tracks to score")
        .input(kTruth, "ground truth at each capture time");
    return add_scoring_params(spec, "tracking", "largest distance still a match");
  }

  explicit MotEvaluator(NodeInit& init) : MotEvaluator(scoring_params(init)) {}
  explicit MotEvaluator(const ScoringParams& p)
      : radius_(p.match_radius_m), skip_(p.skip_first_s), max_lag_(p.max_lag_s), lag_step_(p.lag_step_s),
        section_(p.section) {}

  void process(Context& ctx) override {
    if (ctx.triggered_by(kTruth)) {
      pairing_.add_truth(ctx.get(kTruth));
    } else {
      const auto tracks = ctx.get(kTracks);
      pairing_.add(tracks->stamp, tracks, to_seconds(ctx.now()));
    }
    pairing_.pair([this](const msg::Tracks& tracks, const msg::GroundTruth& truth, double arrival) {
      if (to_seconds(truth.stamp) >= skip_) score(tracks, truth, arrival);
    });
  }

  void finish(Context& ctx) override {
    if (pairing_.unpaired() > 0)
      ctx.log().warn("{} track message(s) had no ground truth with their capture time; not scored", pairing_.unpaired());
    const auto s = acc_.summary();
    Eigen::Vector3d rmse = Eigen::Vector3d::Zero();
    if (selected_samples_ > 0) rmse = (selected_sq_ / static_cast<double>(selected_samples_)).cwiseSqrt();
    const double rmse_norm = selected_samples_ ? std::sqrt(selected_sq_.sum() / static_cast<double>(selected_samples_)) : 0.0;
    const auto lag = algorithms::estimate_lag(truth_curve_, selected_curve_, max_lag_, lag_step_);
    nlohmann::json json = {{"frames", s.frames},
                           {"mota", s.mota},
                           {"motp_m", s.motp},
                           {"idf1", s.idf1},
                           {"idsw", s.idsw},
                           {"fp", s.fp},
                           {"fn", s.fn},
                           {"fragmentations", s.fragmentations},
                           {"mostly_tracked", s.mostly_tracked},
                           {"partially_tracked", s.partially_tracked},
                           {"mostly_lost", s.mostly_lost},
                           {"num_objects", s.objects},
                           {"rmse_m", rmse_norm},
                           {"rmse_axes_m", {{"x", rmse.x()}, {"y", rmse.y()}, {"z", rmse.z()}}},
                           {"selected_frames", selected_samples_},
                           {"lag_s", lag ? nlohmann::json(*lag) : nlohmann::json(nullptr)}};
    const std::string md = fmt::format(
        "| frames | MOTA | MOTP [m] | IDF1 | IDSW | FP | FN | FRAG | MT/PT/ML | target RMSE [m] | lag [s] |\n"
        "|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|---:|\n"
        "| {} | {:.4f} | {:.3f} | {:.3f} | {} | {} | {} | {} | {}/{}/{} | {:.3f} | {} |\n",
        s.frames, s.mota, s.motp, s.idf1, s.idsw, s.fp, s.fn, s.fragmentations, s.mostly_tracked, s.partially_tracked,
        s.mostly_lost, rmse_norm, lag ? fmt::format("{:.3f}", *lag) : "n/a");
    ctx.set_report_section(section_, json, md);
  }

 private:
  void score(const msg::Tracks& tracks, const msg::GroundTruth& truth, double arrival_s) {
    std::vector<std::uint64_t> objects, hypotheses;
    for (const auto& o : truth.objects) objects.push_back(o.id);
    for (const auto& t : tracks.items) hypotheses.push_back(t.id);
    Eigen::MatrixXd d(static_cast<Eigen::Index>(objects.size()), static_cast<Eigen::Index>(hypotheses.size()));
    for (std::size_t i = 0; i < objects.size(); ++i)
      for (std::size_t j = 0; j < hypotheses.size(); ++j) {
        const double v = (truth.objects[i].position_camera - tracks.items[j].position()).norm();
        d(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) =
            v <= radius_ ? v : std::numeric_limits<double>::quiet_NaN();
      }
    acc_.update(objects, hypotheses, d);

    // The selected track against the object it is matched to this frame.
    if (!truth.objects.empty()) truth_curve_.push_back({to_seconds(truth.stamp), truth.objects.front().position_camera});
    const msg::Track* selected = tracks.selected();
    if (!selected) return;
    for (const auto& [i, j] : acc_.last_matches()) {
      if (tracks.items[static_cast<std::size_t>(j)].id != selected->id) continue;
      const Eigen::Vector3d e = selected->position() - truth.objects[static_cast<std::size_t>(i)].position_camera;
      selected_sq_ += e.cwiseProduct(e);
      ++selected_samples_;
      if (i == 0) selected_curve_.push_back({arrival_s, selected->position()});
    }
  }

  double radius_, skip_, max_lag_, lag_step_;
  std::string section_;
  algorithms::ClearMotAccumulator acc_;
  TruthPairing<msg::Tracks> pairing_;
  Eigen::Vector3d selected_sq_ = Eigen::Vector3d::Zero();
  std::uint64_t selected_samples_ = 0;
  std::vector<algorithms::TimedPoint> truth_curve_, selected_curve_;
};
KESTREL_REGISTER_NODE(MotEvaluator)

}  // namespace kestrel::evaluation
