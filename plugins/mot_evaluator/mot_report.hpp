#pragma once
// The tracking evaluator's section of the run report: values (null where undefined), report.md
// text ("undefined" there) and the unit and direction of every metric.
#include "kestrel/evaluation/report_section.hpp"
#include "mot_scoring.hpp"

namespace kestrel::evaluation {

/// CLEAR-MOT and IDF1 over all tracks, the selected track's RMSE and lag, and the target's own
/// score. MOTA, MOTP, IDF1, RMSE, lag and target.mota are null when there is nothing to measure
/// them on (no ground truth, no matches, no frame with the target selected).
ReportSection tracking_report(const TrackingSummary& summary);

}  // namespace kestrel::evaluation
