#include "detection_report.hpp"

#include <kestrel/evaluation/body_axes.hpp>

namespace kestrel::evaluation {

namespace {

std::optional<double> axis(const std::optional<Eigen::Vector3d>& v, int i) {
  return v ? std::optional<double>((*v)[i]) : std::nullopt;
}

}  // namespace

ReportSection detection_report(const DetectionSummary& s) {
  const std::optional<Eigen::Vector3d> rmse_body =
      s.rmse ? std::optional<Eigen::Vector3d>(rms_in_body_axes(*s.rmse)) : std::nullopt;
  const std::optional<Eigen::Vector3d> bias_body =
      s.mean_error ? std::optional<Eigen::Vector3d>(bias_in_body_axes(*s.mean_error)) : std::nullopt;
  ReportSection section;
  section.quantity("frames", s.frames)
      .metric("precision", number_or_null(s.precision), "", Better::higher)
      .metric("recall", number_or_null(s.recall), "", Better::higher)
      .metric("tp", s.tp, "", Better::higher)
      .metric("fp", s.fp, "", Better::lower)
      .metric("fn", s.fn, "", Better::lower)
      .metric("rmse_m", axes_or_null(s.rmse), "m", Better::lower)
      .metric("mean_error_m", axes_or_null(s.mean_error), "m", Better::nearer_zero)
      .metric("rmse_body_m", axes_or_null(rmse_body), "m", Better::lower)
      .metric("bias_body_m", axes_or_null(bias_body), "m", Better::nearer_zero)
      .metric("lag_s", number_or_null(s.lag_s), "s", Better::nearer_zero);
  const auto f3 = [](const std::optional<double>& v) { return text_or_undefined(v, "{:.3f}"); };
  const auto bias = [](const std::optional<double>& v) { return text_or_undefined(v, "{:+.3f} m"); };
  section.markdown(fmt::format(
      "| frames | precision | recall | TP | FP | FN | RMSE x [m] | RMSE y [m] | RMSE z [m] | lag [s] |\n"
      "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n"
      "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n\n"
      "Mean error (bias) of matched detections: x {}, y {}, z {}.\n\n"
      "In the hunter's body axes (FLU: x forward = depth, y left, z up; the paper's Table 1): RMSE x {}, y {}, "
      "z {} m; bias x {}, y {}, z {}.\n",
      s.frames, f3(s.precision), f3(s.recall), s.tp, s.fp, s.fn, f3(axis(s.rmse, 0)), f3(axis(s.rmse, 1)),
      f3(axis(s.rmse, 2)), f3(s.lag_s), bias(axis(s.mean_error, 0)), bias(axis(s.mean_error, 1)),
      bias(axis(s.mean_error, 2)), f3(axis(rmse_body, 0)), f3(axis(rmse_body, 1)), f3(axis(rmse_body, 2)),
      bias(axis(bias_body, 0)), bias(axis(bias_body, 1)), bias(axis(bias_body, 2))));
  if (!s.precision || !s.recall || !s.rmse || !s.lag_s)
    section.append_markdown(
        "\nUndefined: a figure with nothing to measure it on (no detections, nothing to find, no matches, or "
        "too few to correlate for the lag).\n");
  return section;
}

}  // namespace kestrel::evaluation
