// The `mot_evaluator` node: CLEAR-MOT (MOTA, MOTP, IDSW, fragmentations, MT/PT/ML), IDF1, the
// selected track's RMSE and the tracking lag, and the selected target's own score, against the
// simulator's ground truth.
#include <fmt/format.h>

#include <kestrel/algorithms/mot_metrics.hpp>
#include <kestrel/evaluation/scoring_params.hpp>
#include <kestrel/evaluation/truth_pairing.hpp>
#include <kestrel/plugin.hpp>

#include "mot_scoring.hpp"

namespace kestrel::evaluation {

class MotEvaluator final : public Node {
 public:
  static constexpr Input<msg::Tracks> kTracks{"tracks"};
  static constexpr Input<msg::GroundTruth> kTruth{"truth"};

  static NodeSpec spec() {
    NodeSpec spec =
        NodeSpec("mot_evaluator", "CLEAR-MOT and IDF1 of tracks against ground truth, and the target's RMSE and lag")
            .details(
                "Each frame, tracks are paired with the truth of the same capture time. Correspondences from earlier "
                "frames are kept while their distance stays within match_radius_m; the rest are assigned by the "
                "Hungarian method; a ground-truth object matched to another track than before is an identity "
                "switch (MOT16, py-motmetrics). An intruder out of the camera's view is neither missed nor found, and "
                "a "
                "track that follows it is not a false positive (MOTChallenge's distractors). Also the RMSE of the "
                "selected track against the truth object it "
                "follows, and the tracking lag by cross-correlation. The selected track alone is scored too, as "
                "the aiming sees it: frames it is on an intruder, on nothing (off target), missing while an intruder "
                "is there, and switches between intruders; target.mota = 1 - (missing + off + switches) / frames "
                "with an intruder. Adds \"tracking\" to report.json.")
            .input(kTracks, "tracks to score")
            .input(kTruth, "ground truth at each capture time");
    return add_scoring_params(spec, "tracking", "largest distance still a match");
  }

  explicit MotEvaluator(NodeInit& init) : MotEvaluator(scoring_params(init)) {}
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
    const TrackingSummary t = scorer_.summary(params_.max_lag_s, params_.lag_step_s);
    const algorithms::MotSummary& s = t.mot;
    // The CLEAR-MOT keys are named once, for this node and `kestrel mot` alike.
    nlohmann::json json = algorithms::mot_summary_json(s);
    json.update({{"rmse_m", t.rmse},
                 {"rmse_axes_m", {{"x", t.rmse_axes.x()}, {"y", t.rmse_axes.y()}, {"z", t.rmse_axes.z()}}},
                 {"selected_frames", t.selected_frames},
                 {"lag_s", t.lag_s ? nlohmann::json(*t.lag_s) : nlohmann::json(nullptr)},
                 {"target",
                  {{"mota", t.target.mota()},
                   {"frames", t.target.frames},
                   {"on_target", t.target.on},
                   {"off_target", t.target.off},
                   {"missing", t.target.missing},
                   {"switches", t.target.switches}}}});
    // Messages that found no partner, so were not scored: a lossy chain shows here.
    json["unpaired"] = {{"messages", pairing_.unpaired_items()}, {"truths", pairing_.unpaired_truths()}};
    const std::string md = fmt::format(
        "| frames | MOTA | MOTP [m] | IDF1 | IDSW | FP | FN | FRAG | MT/PT/ML | target RMSE [m] | lag [s] |\n"
        "|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|---:|\n"
        "| {} | {:.4f} | {:.3f} | {:.3f} | {} | {} | {} | {} | {}/{}/{} | {:.3f} | {} |\n\n"
        "The selected target alone (what the aiming follows): target MOTA {:.4f}; on an intruder in {} of {} "
        "frames, on nothing in {}, missing in {}, {} switch(es) between intruders. Not scored for want of a partner: "
        "{} "
        "track message(s) without ground truth, {} ground truth frame(s) without tracks.\n",
        s.frames, s.mota, s.motp, s.idf1, s.idsw, s.fp, s.fn, s.fragmentations, s.mostly_tracked, s.partially_tracked,
        s.mostly_lost, t.rmse, t.lag_s ? fmt::format("{:.3f}", *t.lag_s) : "n/a", t.target.mota(), t.target.on,
        t.target.frames, t.target.off, t.target.missing, t.target.switches, pairing_.unpaired_items(),
        pairing_.unpaired_truths());
    ctx.set_report_section(params_.section, json, md);
  }

 private:
  ScoringParams params_;
  TrackingScorer scorer_;
  TruthPairing<msg::Tracks> pairing_;
};
KESTREL_REGISTER_NODE(MotEvaluator)

}  // namespace kestrel::evaluation
