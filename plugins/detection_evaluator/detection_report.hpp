#pragma once
// The detection evaluator's section of the run report: values (null where undefined), report.md
// text ("undefined" there) and the unit and direction of every metric.
#include "detection_scoring.hpp"
#include "kestrel/evaluation/report_section.hpp"

namespace kestrel::evaluation {

/// frames, precision, recall, tp, fp, fn, rmse_m {x, y, z}, mean_error_m {x, y, z} and lag_s.
ReportSection detection_report(const DetectionSummary& summary);

}  // namespace kestrel::evaluation
