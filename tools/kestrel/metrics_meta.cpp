#include "metrics_meta.hpp"

namespace kestrel::cli {

namespace {

// Lenient: a malformed entry describes what it can, and never stops a summary.
MetricMeta parse(const nlohmann::json& entry) {
  MetricMeta m;
  if (!entry.is_object()) return m;
  if (const auto it = entry.find("unit"); it != entry.end() && it->is_string()) m.unit = it->get<std::string>();
  if (const auto it = entry.find("higher_is_better"); it != entry.end() && it->is_boolean())
    m.higher_is_better = it->get<bool>();
  if (const auto it = entry.find("by_magnitude"); it != entry.end() && it->is_boolean())
    m.by_magnitude = it->get<bool>();
  return m;
}

}  // namespace

void MetricsMeta::add(const nlohmann::json& report) {
  if (!report.is_object()) return;
  const auto meta = report.find("metrics_meta");
  if (meta == report.end() || !meta->is_object()) return;
  for (const auto& [key, entry] : meta->items()) {
    const MetricMeta m = parse(entry);
    const auto [it, added] = entries_.emplace(key, m);
    if (added || it->second == m) continue;
    if (it->second.higher_is_better != m.higher_is_better || it->second.by_magnitude != m.by_magnitude) {
      it->second.higher_is_better.reset();
      it->second.by_magnitude = false;
    }
    conflicts_.insert(key);
  }
}

const MetricMeta* MetricsMeta::find(const std::string& metric) const {
  for (std::string path = metric;;) {
    if (const auto it = entries_.find(path); it != entries_.end()) return &it->second;
    const auto dot = path.rfind('.');
    if (dot == std::string::npos) return nullptr;
    path.resize(dot);
  }
}

int MetricsMeta::direction(const std::string& metric) const {
  const MetricMeta* m = find(metric);
  if (!m || !m->higher_is_better) return 0;
  return *m->higher_is_better ? 1 : -1;
}

bool MetricsMeta::by_magnitude(const std::string& metric) const {
  const MetricMeta* m = find(metric);
  return m && m->by_magnitude;
}

std::string MetricsMeta::label(const std::string& metric) const {
  const MetricMeta* m = find(metric);
  return m && !m->unit.empty() ? metric + " [" + m->unit + "]" : metric;
}

std::string MetricsMeta::better_text(const std::string& metric) const {
  switch (direction(metric)) {
    case 1:
      return by_magnitude(metric) ? "larger magnitude is better" : "higher is better";
    case -1:
      return by_magnitude(metric) ? "smaller magnitude is better" : "lower is better";
    default:
      return "";
  }
}

nlohmann::json MetricsMeta::to_json() const {
  nlohmann::json json = nlohmann::json::object();
  for (const auto& [key, m] : entries_) {
    nlohmann::json entry = {{"unit", m.unit}};
    if (m.higher_is_better) entry["higher_is_better"] = *m.higher_is_better;
    if (m.by_magnitude) entry["by_magnitude"] = true;
    json[key] = entry;
  }
  return json;
}

}  // namespace kestrel::cli
