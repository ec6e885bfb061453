#include "mot_report.hpp"

#include <kestrel/algorithms/mot_metrics.hpp>
#include <kestrel/evaluation/body_axes.hpp>

namespace kestrel::evaluation {

namespace {

std::optional<double> defined_if(bool defined, double value) {
  return defined ? std::optional<double>(value) : std::nullopt;
}

}  // namespace

ReportSection tracking_report(const TrackingSummary& t) {
  const algorithms::MotSummary& s = t.mot;
  // The accumulator reports 1 (or 0) for ratios over nothing; here they are undefined.
  const auto mota = defined_if(s.objects > 0, s.mota);
  const auto motp = defined_if(s.matches > 0, s.motp);
  const auto idf1 = defined_if(s.objects + s.hypotheses > 0, s.idf1);
  const bool selected = t.selected_frames > 0;
  const auto rmse = defined_if(selected, t.rmse);
  const auto target_mota = defined_if(t.target.frames > 0, t.target.mota());

  ReportSection section;
  // The CLEAR-MOT keys are named once (kestrel/algorithms/mot_metrics.hpp), for this node and
  // `kestrel mot` alike; ratios over nothing are then made undefined here.
  const nlohmann::json clear_mot = algorithms::mot_summary_json(s);
  const nlohmann::json clear_mot_meta = algorithms::mot_summary_meta("");
  for (const auto& [key, value] : clear_mot.items()) {
    const nlohmann::json& meta = clear_mot_meta.at(key);
    const Better better = !meta.contains("higher_is_better")     ? Better::neither
                          : meta["higher_is_better"].get<bool>() ? Better::higher
                                                                 : Better::lower;
    section.metric(key, value, meta["unit"].get<std::string>(), better);
  }
  section.metric("mota", number_or_null(mota), "", Better::higher)
      .metric("motp_m", number_or_null(motp), "m", Better::lower)
      .metric("idf1", number_or_null(idf1), "", Better::higher)
      .metric("rmse_m", number_or_null(rmse), "m", Better::lower)
      .metric("rmse_axes_m",
              {{"x", number_or_null(defined_if(selected, t.rmse_axes.x()))},
               {"y", number_or_null(defined_if(selected, t.rmse_axes.y()))},
               {"z", number_or_null(defined_if(selected, t.rmse_axes.z()))}},
              "m", Better::lower)
      .metric("rmse_body_m",
              axes_or_null(selected ? std::optional<Eigen::Vector3d>(rms_in_body_axes(t.rmse_axes)) : std::nullopt),
              "m", Better::lower)
      .metric("bias_body_m",
              axes_or_null(selected ? std::optional<Eigen::Vector3d>(bias_in_body_axes(t.bias_axes)) : std::nullopt),
              "m", Better::nearer_zero)
      .metric("selected_frames", t.selected_frames, "", Better::higher)
      .metric("lag_s", number_or_null(t.lag_s), "s", Better::nearer_zero)
      .metric("target.mota", number_or_null(target_mota), "", Better::higher)
      .quantity("target.frames", t.target.frames)
      .metric("target.on_target", t.target.on, "", Better::higher)
      .metric("target.off_target", t.target.off, "", Better::lower)
      .metric("target.missing", t.target.missing, "", Better::lower)
      .metric("target.switches", t.target.switches, "", Better::lower);
  const auto f = [](const std::optional<double>& v, fmt::format_string<double> spec) {
    return text_or_undefined(v, spec);
  };
  section.markdown(fmt::format(
      "| frames | MOTA | MOTP [m] | IDF1 | IDSW | FP | FN | FRAG | MT/PT/ML | target RMSE [m] | lag [s] |\n"
      "|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|---:|\n"
      "| {} | {} | {} | {} | {} | {} | {} | {} | {}/{}/{} | {} | {} |\n\n"
      "The selected target alone (what the aiming follows): target MOTA {}; on an intruder in {} of {} "
      "frames, on nothing in {}, missing in {}, {} switch(es) between intruders.\n",
      s.frames, f(mota, "{:.4f}"), f(motp, "{:.3f}"), f(idf1, "{:.3f}"), s.idsw, s.fp, s.fn, s.fragmentations,
      s.mostly_tracked, s.partially_tracked, s.mostly_lost, f(rmse, "{:.3f}"), f(t.lag_s, "{:.3f}"),
      f(target_mota, "{:.4f}"), t.target.on, t.target.frames, t.target.off, t.target.missing, t.target.switches));
  if (selected) {
    const Eigen::Vector3d body = rms_in_body_axes(t.rmse_axes), bias = bias_in_body_axes(t.bias_axes);
    section.append_markdown(fmt::format(
        "\nThe selected track's error in the hunter's body axes (FLU: x forward = depth, y left, z up; the paper's "
        "axes): RMSE x {:.3f}, y {:.3f}, z {:.3f} m; bias x {:+.3f}, y {:+.3f}, z {:+.3f} m.\n",
        body.x(), body.y(), body.z(), bias.x(), bias.y(), bias.z()));
  }
  if (!mota || !motp || !idf1 || !rmse || !t.lag_s || !target_mota)
    section.append_markdown(
        "\nUndefined: a figure with nothing to measure it on (no ground truth, no matches, no frame with the target "
        "on an intruder, or too few to correlate for the lag).\n");
  return section;
}

}  // namespace kestrel::evaluation
