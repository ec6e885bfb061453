#include "kestrel/report_section.hpp"

#include "kestrel/error.hpp"

namespace kestrel {

MetricMeta metric_meta(std::string_view unit, Better better) {
  switch (better) {
    case Better::higher:
      return {std::string(unit), true, false};
    case Better::lower:
      return {std::string(unit), false, false};
    case Better::nearer_zero:
      return {std::string(unit), false, true};
    case Better::neither:
      break;
  }
  return {std::string(unit), std::nullopt, false};
}

void ReportSection::set(std::string_view path, nlohmann::json value) {
  if (path.empty() || path.front() == '.' || path.back() == '.')
    throw Error("report section: '" + std::string(path) + "' is not a dotted key");
  nlohmann::json* node = &values_;
  std::string_view rest = path;
  for (auto dot = rest.find('.'); dot != std::string_view::npos; dot = rest.find('.')) {
    nlohmann::json& child = (*node)[std::string(rest.substr(0, dot))];
    if (child.is_null()) child = nlohmann::json::object();
    if (!child.is_object())
      throw Error("report section: '" + std::string(path) + "' lies below a value that is not a table");
    node = &child;
    rest.remove_prefix(dot + 1);
  }
  (*node)[std::string(rest)] = std::move(value);
}

ReportSection& ReportSection::metric(std::string_view path, nlohmann::json value, std::string_view unit,
                                     Better better) {
  set(path, std::move(value));
  metrics_[std::string(path)] = metric_meta(unit, better);
  return *this;
}

namespace {

bool holds_a_number(const nlohmann::json& value) {
  if (value.is_number()) return true;
  if (value.is_structured())
    for (const auto& v : value)
      if (holds_a_number(v)) return true;
  return false;
}

}  // namespace

ReportSection& ReportSection::info(std::string_view path, nlohmann::json value) {
  // A number is always a metric or a quantity, so that sweep, ab and plot know how to read it.
  if (holds_a_number(value))
    throw Error("report section: '" + std::string(path) +
                "' holds a number; set it with metric() or quantity() to say its unit and direction");
  set(path, std::move(value));
  return *this;
}

ReportSection& ReportSection::markdown(std::string text) {
  markdown_ = std::move(text);
  return *this;
}

ReportSection& ReportSection::append_markdown(std::string_view text) {
  markdown_ += text;
  return *this;
}

}  // namespace kestrel
