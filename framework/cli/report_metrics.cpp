#include "report_metrics.hpp"

#include <fstream>
#include <set>

namespace kestrel::cli {

namespace {

void flatten(const nlohmann::json& value, const std::string& prefix, Metrics& out) {
  if (value.is_object()) {
    for (const auto& [k, v] : value.items()) flatten(v, prefix + "." + k, out);
  } else if (value.is_number()) {
    out[prefix] = value.get<double>();
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
  static const std::set<std::string> runtime_keys = {"kestrel_version", "graph",       "outcome", "errors",
                                                     "run_time_s",      "wall_time_s", "stats"};
  Metrics out;
  if (!report.is_object()) return out;
  for (const auto& [key, value] : report.items())
    if (!runtime_keys.count(key)) flatten(value, key, out);
  return out;
}

int better_direction(const std::string& metric) {
  if (metric.find("mean_error") != std::string::npos) return 0;  // a bias: neither way is better
  const std::string name = metric.substr(metric.rfind('.') + 1);
  for (const char* up : {"mota", "idf1", "precision", "recall", "tp", "mostly_tracked", "selected_frames", "on_target"})
    if (name == up) return 1;
  for (const char* down : {"motp_m", "idsw", "fp", "fn", "fragmentations", "mostly_lost", "rmse_m", "x", "y", "z",
                           "lag_s", "switches", "off_target", "missing"})
    if (name == down) return -1;
  if (metric.find("rmse") != std::string::npos) return -1;
  return 0;
}

bool by_magnitude(const std::string& metric) { return metric.substr(metric.rfind('.') + 1) == "lag_s"; }

bool headline(const std::string& metric) {
  static const std::set<std::string> names = {"mota",      "motp_m", "idf1",   "idsw",  "fp",      "fn",
                                              "precision", "recall", "rmse_m", "lag_s", "switches"};
  return names.count(metric.substr(metric.rfind('.') + 1)) > 0 || metric.find(".rmse_m.") != std::string::npos;
}

}  // namespace kestrel::cli
