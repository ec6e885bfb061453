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
  section.values = algorithms::mot_summary_json(s);
  section.values["mota"] = number_or_null(mota);
  section.values["motp_m"] = number_or_null(motp);
  section.values["idf1"] = number_or_null(idf1);
  section.values.update(
      {{"rmse_m", number_or_null(rmse)},
       {"rmse_axes_m",
        {{"x", number_or_null(defined_if(selected, t.rmse_axes.x()))},
         {"y", number_or_null(defined_if(selected, t.rmse_axes.y()))},
         {"z", number_or_null(defined_if(selected, t.rmse_axes.z()))}}},
       {"rmse_body_m",
        axes_or_null(selected ? std::optional<Eigen::Vector3d>(rms_in_body_axes(t.rmse_axes)) : std::nullopt)},
       {"bias_body_m",
        axes_or_null(selected ? std::optional<Eigen::Vector3d>(bias_in_body_axes(t.bias_axes)) : std::nullopt)},
       {"selected_frames", t.selected_frames},
       {"lag_s", number_or_null(t.lag_s)},
       {"target",
        {{"mota", number_or_null(target_mota)},
         {"frames", t.target.frames},
         {"on_target", t.target.on},
         {"off_target", t.target.off},
         {"missing", t.target.missing},
         {"switches", t.target.switches}}}});
  const nlohmann::json clear_mot_meta = algorithms::mot_summary_meta("");
  for (auto it = clear_mot_meta.begin(); it != clear_mot_meta.end(); ++it) {
    kestrel::MetricMeta meta;
    meta.unit = it.value()["unit"].get<std::string>();
    meta.higher_is_better = it.value().contains("higher_is_better")
                                ? std::optional<bool>(it.value()["higher_is_better"].get<bool>())
                                : std::nullopt;
    section.metrics[it.key()] = meta;
  }
  section.metrics.insert({{"rmse_m", {"m", false, false}},
                          {"rmse_axes_m", {"m", false, false}},
                          {"rmse_body_m", {"m", false, false}},
                          {"bias_body_m", {"m", false, true}},
                          {"selected_frames", {"", true, false}},
                          {"lag_s", {"s", false, true}},
                          {"target.mota", {"", true, false}},
                          {"target.frames", {"", std::nullopt, false}},
                          {"target.on_target", {"", true, false}},
                          {"target.off_target", {"", false, false}},
                          {"target.missing", {"", false, false}},
                          {"target.switches", {"", false, false}}});
  const auto f = [](const std::optional<double>& v, fmt::format_string<double> spec) {
    return text_or_undefined(v, spec);
  };
  section.markdown = fmt::format(
      "| frames | MOTA | MOTP [m] | IDF1 | IDSW | FP | FN | FRAG | MT/PT/ML | target RMSE [m] | lag [s] |\n"
      "|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|---:|\n"
      "| {} | {} | {} | {} | {} | {} | {} | {} | {}/{}/{} | {} | {} |\n\n"
      "The selected target alone (what the aiming follows): target MOTA {}; on an intruder in {} of {} "
      "frames, on nothing in {}, missing in {}, {} switch(es) between intruders.\n",
      s.frames, f(mota, "{:.4f}"), f(motp, "{:.3f}"), f(idf1, "{:.3f}"), s.idsw, s.fp, s.fn, s.fragmentations,
      s.mostly_tracked, s.partially_tracked, s.mostly_lost, f(rmse, "{:.3f}"), f(t.lag_s, "{:.3f}"),
      f(target_mota, "{:.4f}"), t.target.on, t.target.frames, t.target.off, t.target.missing, t.target.switches);
  if (selected) {
    const Eigen::Vector3d body = rms_in_body_axes(t.rmse_axes), bias = bias_in_body_axes(t.bias_axes);
    section.markdown += fmt::format(
        "\nThe selected track's error in the hunter's body axes (FLU: x forward = depth, y left, z up; the paper's "
        "axes): RMSE x {:.3f}, y {:.3f}, z {:.3f} m; bias x {:+.3f}, y {:+.3f}, z {:+.3f} m.\n",
        body.x(), body.y(), body.z(), bias.x(), bias.y(), bias.z());
  }
  if (!mota || !motp || !idf1 || !rmse || !t.lag_s || !target_mota)
    section.markdown +=
        "\nUndefined: a figure with nothing to measure it on (no ground truth, no matches, no frame with the target "
        "on an intruder, or too few to correlate for the lag).\n";
  return section;
}

}  // namespace kestrel::evaluation
