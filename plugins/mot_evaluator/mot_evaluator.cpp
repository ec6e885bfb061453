// The `mot_evaluator` node: CLEAR-MOT (MOTA, MOTP, IDSW, fragmentations, MT/PT/ML), IDF1, the
// selected track's RMSE and the tracking lag, and the selected target's own score, against the
// simulator's ground truth.
#include <fmt/format.h>

#include <kestrel/algorithms/mot_metrics.hpp>
#include <kestrel/evaluation/scoring_params.hpp>
#include <kestrel/evaluation/truth_pairing.hpp>
#include <kestrel/plugin.hpp>

#include "mot_report.hpp"
#include "mot_scoring.hpp"

namespace kestrel::evaluation {

class MotEvaluator final : public Node {
 public:
  static constexpr Input<msg::Tracks> kTracks{"tracks"};
  static constexpr Input<msg::GroundTruth> kTruth{"truth"};

  struct Config {
    ScoringParams scoring{.section = "tracking"};
  };

  static NodeSpec spec() {
    ConfigSpec<Config> c;
    declare_scoring_params(c, &Config::scoring, "largest distance still a match");
    return NodeSpec("mot_evaluator", "CLEAR-MOT and IDF1 of tracks against ground truth, and the target's RMSE and lag")
        .details(
            "Each frame, tracks are paired with the truth of the same capture time. Correspondences from earlier "
            "frames are kept while their distance stays within match_radius_m; the rest are assigned by the "
            "Hungarian method; a ground-truth object matched to another track than before is an identity switch "
            "(MOT16, py-motmetrics). An intruder out of the camera's view is neither missed nor found, and a track "
            "that follows it is not a false positive (MOTChallenge's distractors). Also the RMSE of the selected "
            "track against the truth object it follows, and the tracking lag by cross-correlation. The selected "
            "track alone is scored too, as the aiming sees it: frames it is on an intruder, on nothing (off "
            "target), missing while an intruder is there, and switches between intruders; target.mota = 1 - "
            "(missing + off + switches) / frames with an intruder. A figure with nothing to measure it on (MOTA "
            "without ground truth, MOTP or RMSE without matches) is null in report.json and \"undefined\" in "
            "report.md. Adds \"tracking\" to report.json.")
        .input(kTracks, "tracks to score")
        .input(kTruth, "ground truth at each capture time")
        .config(std::move(c));
  }

  explicit MotEvaluator(NodeInit& init) : MotEvaluator(init.config<Config>().scoring) {}
  explicit MotEvaluator(const ScoringParams& p) : params_(p), scorer_(p.match_radius_m, p.skip_first_s) {}

  void process(Context& ctx) override {
    if (ctx.triggered_by(kTruth)) {
      pairing_.add_truth(ctx.get(kTruth));
    } else {
      const auto tracks = ctx.get(kTracks);
      pairing_.add(tracks->stamp, tracks, to_seconds(ctx.now()));
    }
    pairing_.pair([this](const msg::Tracks& tracks, const msg::GroundTruth& truth, double arrival) {
      scorer_.add_frame(tracks, truth, arrival);
    });
  }

  void finish(Context& ctx) override {
    if (pairing_.unpaired_items() > 0)
      ctx.log().warn("{} track message(s) had no ground truth with their capture time; not scored",
                     pairing_.unpaired_items());
    ReportSection section = tracking_report(scorer_.summary(params_.max_lag_s, params_.lag_step_s));
    add_unpaired(section, pairing_.unpaired_items(), pairing_.unpaired_truths());
    ctx.set_report_section(params_.section, section);
  }

 private:
  ScoringParams params_;
  TrackingScorer scorer_;
  TruthPairing<msg::Tracks> pairing_;
};
KESTREL_REGISTER_NODE(MotEvaluator)

}  // namespace kestrel::evaluation
