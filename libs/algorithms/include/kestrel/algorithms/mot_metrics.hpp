#pragma once
// The CLEAR-MOT and identity metrics as reports name them, in one place: the mot_evaluator
// node's "tracking" section and `kestrel mot --json` both write a MotSummary with these keys,
// and describe them in metrics_meta with these units and directions.
#include <nlohmann/json.hpp>
#include <string>

#include "kestrel/algorithms/clear_mot.hpp"

namespace kestrel::algorithms {

/// The summary as report keys: frames, num_objects, matches, mota, motp_m, idf1, idp, idr, idsw,
/// fp, fn, fragmentations, mostly_tracked, partially_tracked, mostly_lost. MOTP is the mean
/// match distance, in metres when matches are by distance.
nlohmann::json mot_summary_json(const MotSummary& s);

/// The metrics_meta entries of those keys, each "prefix.key" (or "key" for an empty prefix):
/// {"unit": ..., "higher_is_better": ...}, the direction left out where neither is better.
nlohmann::json mot_summary_meta(const std::string& prefix);

}  // namespace kestrel::algorithms
