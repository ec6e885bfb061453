#pragma once
// An evaluator's section of the run report: its values, its Markdown, and how to read each
// metric in it (unit and direction). Built by a pure function that tests can call, then handed to
// the run by publish_section.
#include <fmt/format.h>

#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "kestrel/node.hpp"
#include "kestrel/report.hpp"

namespace kestrel::evaluation {

struct ReportSection {
  nlohmann::json values = nlohmann::json::object();
  std::string markdown;
  /// Keyed by the path inside the section ("rmse_m"); an entry covers the keys below it too
  /// ("rmse_m.x").
  std::map<std::string, MetricMeta> metrics;
};

/// A metric that may be undefined: the number, or null.
inline nlohmann::json number_or_null(const std::optional<double>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

/// A metric that may be undefined, for report.md: formatted with `spec` (e.g. "{:.3f}"), or
/// "undefined".
inline std::string text_or_undefined(const std::optional<double>& v, fmt::format_string<double> spec) {
  return v ? fmt::format(spec, double{*v}) : std::string("undefined");
}

/// Adds what the evaluator could not score for want of a partner (TruthPairing's counts): a lossy
/// chain shows here.
inline void add_unpaired(ReportSection& section, std::uint64_t messages, std::uint64_t truths) {
  section.values["unpaired"] = {{"messages", messages}, {"truths", truths}};
  section.metrics["unpaired"] = MetricMeta{"", false, false};
  section.markdown += fmt::format(
      "\nNot scored for want of a partner: {} message(s) without ground truth, {} ground truth frame(s) without a "
      "message.\n",
      messages, truths);
}

/// Sets the report section `key` and describes each of its metrics as "key.path".
inline void publish_section(Context& ctx, const std::string& key, const ReportSection& section) {
  ctx.set_report_section(key, section.values, section.markdown);
  for (const auto& [path, meta] : section.metrics) {
    if (meta.higher_is_better)
      ctx.describe_metric(key + "." + path, meta.unit, *meta.higher_is_better, meta.by_magnitude);
    else
      ctx.describe_quantity(key + "." + path, meta.unit);
  }
}

/// The leaf keys of the section's values (dotted paths) that no metric entry covers. Empty when
/// every reported value says how to read it.
inline std::vector<std::string> undescribed_metrics(const ReportSection& section) {
  std::vector<std::string> missing;
  const auto covered = [&](std::string path) {
    for (;;) {
      if (section.metrics.count(path)) return true;
      const auto dot = path.rfind('.');
      if (dot == std::string::npos) return false;
      path.resize(dot);
    }
  };
  const auto walk = [&](const auto& self, const nlohmann::json& value, const std::string& path) -> void {
    if (value.is_object()) {
      for (const auto& [k, v] : value.items()) self(self, v, path.empty() ? k : path + "." + k);
    } else if (!covered(path)) {
      missing.push_back(path);
    }
  };
  walk(walk, section.values, "");
  return missing;
}

}  // namespace kestrel::evaluation
