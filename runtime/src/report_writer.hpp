#pragma once
// Writes DIR/report.json and its human-readable twin DIR/report.md.
#include <filesystem>
#include <map>

#include "kestrel/report.hpp"
#include "kestrel/runtime/run.hpp"

namespace kestrel::detail {

void write_report(const std::filesystem::path& dir, const RunResult& result,
                  const std::map<std::string, Report::Section>& sections);

/// A JSON object as a two-column Markdown table, nested keys joined with dots.
std::string json_to_markdown_table(const nlohmann::json& value);

}  // namespace kestrel::detail
