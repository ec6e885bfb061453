#pragma once
// How metrics describe themselves: report.json's "metrics_meta", keyed by dotted path, gives
// each metric's unit and which way is better. The experiment commands judge and label metrics
// with it instead of keeping lists of metric names of their own.
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>

#include "kestrel/report_section.hpp"

namespace kestrel::cli {

/// One metric's reading, as the node that reported it declared it (kestrel/report_section.hpp).
using MetricMeta = kestrel::MetricMeta;

/// The metrics_meta of every report read, merged.
class MetricsMeta {
 public:
  /// Adds the report's metrics_meta. Where two reports describe a metric differently, its unit
  /// is the first one's and it gets no direction: no verdict rather than a guessed one.
  void add(const nlohmann::json& report);

  /// The metric's own entry or, failing that, its nearest ancestor's ("detection.rmse_m"
  /// describes "detection.rmse_m.x"); nullptr if neither is described.
  const MetricMeta* find(const std::string& metric) const;

  /// +1 if higher is better, -1 if lower is, 0 if the meta does not say.
  int direction(const std::string& metric) const;
  bool by_magnitude(const std::string& metric) const;

  /// "name [unit]", or the name alone when it has no unit.
  std::string label(const std::string& metric) const;

  /// "higher is better", "lower is better", "smaller magnitude is better" or "".
  std::string better_text(const std::string& metric) const;

  /// Metrics described differently by different reports.
  const std::set<std::string>& conflicts() const { return conflicts_; }

  /// As report.json carries it.
  nlohmann::json to_json() const;

 private:
  std::map<std::string, MetricMeta> entries_;
  std::set<std::string> conflicts_;
};

}  // namespace kestrel::cli
