#pragma once
// One section of the run report as a node fills it: each value is set together with its unit and
// which way it is better, so that a metric is named once. sweep, ab and plot judge runs by what
// the section declares here (report.json's "metrics_meta").
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>

namespace kestrel {

/// How report.json records the reading of one metric: its unit, and which way is better (none for
/// a count that is neither good nor bad). `by_magnitude`: smaller |value| is better whatever the
/// sign (a lag, a bias).
struct MetricMeta {
  std::string unit;
  std::optional<bool> higher_is_better;  ///< unset: neither way is better
  bool by_magnitude = false;

  bool operator==(const MetricMeta&) const = default;
};

/// Which way a metric is better.
enum class Better {
  higher,       ///< a recall, a capture
  lower,        ///< an RMSE, a count of dropped messages
  nearer_zero,  ///< a bias or a lag: the smaller |value| the better, whatever its sign
  neither,      ///< a count of frames or objects: no verdict
};

/// The values of a report section, how to read each, and its text for report.md.
class ReportSection {
 public:
  /// Sets the value at `path` (dotted inside the section: "recall", "target.mota") and declares its
  /// unit ("" for a ratio or a count) and direction. An object value (axes x, y, z) is read the
  /// same way in each of its keys. Setting a path twice replaces the value and its reading.
  ReportSection& metric(std::string_view path, nlohmann::json value, std::string_view unit, Better better);
  /// A measure with no better direction (frames seen, messages published).
  ReportSection& quantity(std::string_view path, nlohmann::json value, std::string_view unit = {}) {
    return metric(path, std::move(value), unit, Better::neither);
  }
  /// A value that is not a number to compare (a name, a mode): reported, never judged.
  ReportSection& info(std::string_view path, nlohmann::json value);
  /// The section's text in report.md; without it the values are shown as a table.
  ReportSection& markdown(std::string text);
  ReportSection& append_markdown(std::string_view text);

  const nlohmann::json& values() const { return values_; }
  const std::string& markdown() const { return markdown_; }
  /// Keyed by the path inside the section.
  const std::map<std::string, MetricMeta>& metrics() const { return metrics_; }

 private:
  void set(std::string_view path, nlohmann::json value);

  nlohmann::json values_ = nlohmann::json::object();
  std::string markdown_;
  std::map<std::string, MetricMeta> metrics_;
};

/// How report.json records a direction.
MetricMeta metric_meta(std::string_view unit, Better better);

}  // namespace kestrel
