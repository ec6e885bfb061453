#include "report_metrics.hpp"

#include <fstream>
#include <limits>
#include <set>

namespace kestrel::cli {

namespace {

void flatten(const nlohmann::json& value, const std::string& prefix, Metrics& out) {
  if (value.is_object()) {
    for (const auto& [k, v] : value.items()) flatten(v, prefix + "." + k, out);
  } else if (value.is_number()) {
    out[prefix] = value.get<double>();
  } else if (value.is_null()) {
    out[prefix] = std::numeric_limits<double>::quiet_NaN();  // undefined: nothing to measure it on
  }
}

}  // namespace

nlohmann::json read_report(const std::filesystem::path& dir) {
  std::ifstream in(dir / "report.json");
  if (!in) return nullptr;
  nlohmann::json report = nlohmann::json::parse(in, nullptr, false);
  return report.is_discarded() ? nlohmann::json() : report;
}

Metrics report_metrics(const nlohmann::json& report) {
  static const std::set<std::string> runtime_keys = {"kestrel_version", "graph",  "outcome",
                                                     "ended_by",        "errors", "run_time_s",
                                                     "wall_time_s",     "stats",  "metrics_meta"};
  Metrics out;
  if (!report.is_object()) return out;
  for (const auto& [key, value] : report.items())
    if (!runtime_keys.count(key)) flatten(value, key, out);
  return out;
}

}  // namespace kestrel::cli
