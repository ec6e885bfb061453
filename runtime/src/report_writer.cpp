#include "report_writer.hpp"

#include <fmt/format.h>

#include <fstream>

#include "kestrel/error.hpp"

namespace kestrel::detail {

namespace {

void flatten(const nlohmann::json& value, const std::string& prefix,
             std::vector<std::pair<std::string, std::string>>& rows) {
  if (value.is_object() && !value.empty()) {
    for (const auto& [k, v] : value.items()) flatten(v, prefix.empty() ? k : prefix + "." + k, rows);
  } else if (value.is_number_float()) {
    rows.emplace_back(prefix, fmt::format("{:.4g}", value.get<double>()));
  } else if (value.is_null()) {
    rows.emplace_back(prefix, "undefined");  // a metric with nothing to measure (no matches, no frames)
  } else if (value.is_string()) {
    rows.emplace_back(prefix, value.get<std::string>());
  } else {
    rows.emplace_back(prefix, value.dump());
  }
}

void write_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  out.close();  // a full disk shows only when the buffer is flushed
  if (!out) throw Error("cannot write " + path.string());
}

}  // namespace

std::string json_to_markdown_table(const nlohmann::json& value) {
  std::vector<std::pair<std::string, std::string>> rows;
  flatten(value, "", rows);
  std::string md = "| metric | value |\n|---|---|\n";
  for (const auto& [k, v] : rows) md += fmt::format("| {} | {} |\n", k, v);
  return md;
}

void write_report(const std::filesystem::path& dir, const RunResult& result,
                  const std::map<std::string, Report::Section>& sections) {
  write_file(dir / "report.json", result.report.dump(2) + "\n");

  const auto& graph = result.report["graph"];
  std::string md = fmt::format("# kestrel run report: {}\n\n", graph.value("name", std::string("graph")));
  md += fmt::format("- graph: `{}`\n- executor: {}, clock: {}, seed: {}\n- outcome: **{}**\n",
                    graph.value("file", std::string()), graph.value("executor", std::string()),
                    graph.value("clock", std::string()), graph["seed"].dump(),
                    result.report.value("outcome", std::string()));
  md += fmt::format("- run time: {:.2f} s, wall time: {:.2f} s\n", result.sim_time_s, result.wall_time_s);
  if (const nlohmann::json ended = result.report.value("ended_by", nlohmann::json()); ended.is_object())
    md += fmt::format("- ended by node `{}`: {}\n", ended.value("node", std::string()),
                      ended.value("why", std::string()));
  if (!result.errors.empty()) {
    md += "\n## Errors\n\n";
    for (const auto& e : result.errors) md += "- " + e + "\n";
  }
  for (const auto& [key, section] : sections) {
    md += fmt::format("\n## {}\n\n", key);
    md += section.markdown.empty() ? json_to_markdown_table(section.value) : section.markdown;
    if (!md.empty() && md.back() != '\n') md += '\n';
  }
  if (!result.report["artifacts"].empty()) {
    md += "\n## Files\n\n";
    for (const auto& a : result.report["artifacts"]) {
      const std::string file = a["file"].get<std::string>();
      const std::string caption = a["caption"].get<std::string>().empty() ? file : a["caption"].get<std::string>();
      const bool image = file.size() > 4 && file.substr(file.size() - 4) == ".png";
      md += image ? fmt::format("![{}]({})\n\n*{}* ({})\n\n", caption, file, caption, a["node"].get<std::string>())
                  : fmt::format("- [{}]({}): {} ({})\n", file, file, caption, a["node"].get<std::string>());
    }
  }
  md +=
      "\n## Nodes\n\nTimes inside the node (µs), and the age of what it publishes: capture stamp to publication "
      "(ms).\n\n| node | type | in | out | drops | errors | p50 µs | p99 µs | max µs | age p50 ms | age p99 ms |\n"
      "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  const auto age = [](const DurationHistogram& h, double q) {
    return h.count() ? fmt::format("{:.1f}", static_cast<double>(h.quantile(q)) / 1e6) : std::string("-");
  };
  for (const auto& n : result.nodes) {
    md += fmt::format("| {} | {} | {} | {} | {} | {} | {:.1f} | {:.1f} | {:.1f} | {} | {} |\n", n.id, n.type,
                      n.messages_in, n.messages_out, n.drops, n.errors, n.processing.quantile(0.5) / 1e3,
                      n.processing.quantile(0.99) / 1e3, n.processing.max() / 1e3, age(n.latency, 0.5),
                      age(n.latency, 0.99));
  }
  md +=
      "\n## Connections\n\n| connection | policy | delivered | drops | queue high-water |\n|---|---|---:|---:|---:|\n";
  for (const auto& c : result.connections)
    md += fmt::format("| {}{} | {} | {} | {} | {} |\n", c.label, c.delayed ? " (delayed)" : "", c.policy, c.delivered,
                      c.drops, c.high_water);
  write_file(dir / "report.md", md);
}

}  // namespace kestrel::detail
