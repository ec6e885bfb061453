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
/// with dots); the runtime's own keys (stats, graph, metrics_meta, ...) are left out. A metric the
/// report gives as null (undefined: zero denominator, nothing to measure it on) is NaN here, so
/// that consumers can count it and leave it out of means.
Metrics report_metrics(const nlohmann::json& report);

}  // namespace kestrel::cli
