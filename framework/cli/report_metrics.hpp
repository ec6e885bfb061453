#pragma once
// The metrics in a run's report.json, as flat "section.key" names with numeric values.
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

namespace kestrel::cli {

using Metrics = std::map<std::string, double>;

/// The report.json in `dir`; null if the run wrote none or an unreadable one.
nlohmann::json read_report(const std::filesystem::path& dir);

/// The numeric metrics of a report's evaluator sections, as "section.key" (nested keys joined
/// with dots); the runtime's own keys (stats, graph, ...) are left out.
Metrics report_metrics(const nlohmann::json& report);

/// +1 if a larger value of this metric is better, -1 if smaller is better, 0 if unknown.
int better_direction(const std::string& metric);

/// True if the metric is judged by its magnitude (a lag is as bad early as late).
bool by_magnitude(const std::string& metric);

/// The metrics worth a column in a summary table (the CSV and JSON keep every metric).
bool headline(const std::string& metric);

}  // namespace kestrel::cli
