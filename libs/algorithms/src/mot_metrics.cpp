#include "kestrel/algorithms/mot_metrics.hpp"

#include <optional>

namespace kestrel::algorithms {

namespace {

// Each metric once: its key, unit, direction and where it comes from.
struct Described {
  const char* key;
  const char* unit;
  std::optional<bool> higher_is_better;  // unset: a count that is neither good nor bad
  nlohmann::json (*value)(const MotSummary&);
};

const Described kMetrics[] = {
    {"frames", "", std::nullopt, [](const MotSummary& s) -> nlohmann::json { return s.frames; }},
    {"num_objects", "", std::nullopt, [](const MotSummary& s) -> nlohmann::json { return s.objects; }},
    {"matches", "", std::nullopt, [](const MotSummary& s) -> nlohmann::json { return s.matches; }},
    {"mota", "", true, [](const MotSummary& s) -> nlohmann::json { return s.mota; }},
    {"motp_m", "m", false, [](const MotSummary& s) -> nlohmann::json { return s.motp; }},
    {"idf1", "", true, [](const MotSummary& s) -> nlohmann::json { return s.idf1; }},
    {"idp", "", true, [](const MotSummary& s) -> nlohmann::json { return s.idp; }},
    {"idr", "", true, [](const MotSummary& s) -> nlohmann::json { return s.idr; }},
    {"idsw", "", false, [](const MotSummary& s) -> nlohmann::json { return s.idsw; }},
    {"fp", "", false, [](const MotSummary& s) -> nlohmann::json { return s.fp; }},
    {"fn", "", false, [](const MotSummary& s) -> nlohmann::json { return s.fn; }},
    {"fragmentations", "", false, [](const MotSummary& s) -> nlohmann::json { return s.fragmentations; }},
    {"mostly_tracked", "", true, [](const MotSummary& s) -> nlohmann::json { return s.mostly_tracked; }},
    {"partially_tracked", "", std::nullopt, [](const MotSummary& s) -> nlohmann::json { return s.partially_tracked; }},
    {"mostly_lost", "", false, [](const MotSummary& s) -> nlohmann::json { return s.mostly_lost; }},
};

}  // namespace

nlohmann::json mot_summary_json(const MotSummary& s) {
  nlohmann::json json = nlohmann::json::object();
  for (const auto& m : kMetrics) json[m.key] = m.value(s);
  return json;
}

nlohmann::json mot_summary_meta(const std::string& prefix) {
  nlohmann::json meta = nlohmann::json::object();
  for (const auto& m : kMetrics) {
    nlohmann::json entry = {{"unit", m.unit}};
    if (m.higher_is_better) entry["higher_is_better"] = *m.higher_is_better;
    meta[prefix.empty() ? m.key : prefix + "." + m.key] = entry;
  }
  return meta;
}

}  // namespace kestrel::algorithms
