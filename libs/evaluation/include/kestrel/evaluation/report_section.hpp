#pragma once
// Helpers for an evaluator's section of the run report (kestrel::ReportSection), which a pure
// function builds so that tests can call it, and the node hands to Context::set_report_section.
#include <fmt/format.h>

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "kestrel/report_section.hpp"

namespace kestrel::evaluation {

using kestrel::Better;
using kestrel::ReportSection;

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
  section.metric("unpaired", {{"messages", messages}, {"truths", truths}}, "", Better::lower);
  section.append_markdown(fmt::format(
      "\nNot scored for want of a partner: {} message(s) without ground truth, {} ground truth frame(s) without a "
      "message.\n",
      messages, truths));
}

}  // namespace kestrel::evaluation
