#include "case_table.hpp"

#include <fmt/format.h>

#include <charconv>
#include <fstream>
#include <set>

#include "csv_format.hpp"
#include "kestrel/error.hpp"

namespace kestrel::cli {

namespace {

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

// As --set takes it: a node, a dot, a parameter (itself maybe dotted), and no '='.
bool node_param(const std::string& key) {
  const auto dot = key.find('.');
  return dot != std::string::npos && dot > 0 && dot + 1 < key.size() && key.find('=') == std::string::npos;
}

int parse_seed(const std::string& text, const SourceLocation& where) {
  int seed = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), seed);
  if (text.empty() || error != std::errc() || end != text.data() + text.size() || seed < 1)
    throw Error(where, "the seed must be a whole number >= 1, not '" + text + "'");
  return seed;
}

}  // namespace

CaseTable read_case_table(std::istream& in, const std::string& label) {
  const std::vector<CsvRecord> records = read_csv(in, label);
  if (records.empty()) throw Error(label + ": no header row (a node.param per column, and optionally seed)");
  const CsvRecord& header = records.front();
  const SourceLocation header_at{label, header.line, 0};
  CaseTable table;
  std::size_t seed_column = header.cells.size();  // none
  std::set<std::string> names;
  for (std::size_t c = 0; c < header.cells.size(); ++c) {
    const std::string name = trimmed(header.cells[c]);
    if (name.empty()) throw Error(header_at, fmt::format("column {} has no name", c + 1));
    if (!names.insert(name).second) throw Error(header_at, "column '" + name + "' appears twice");
    if (name == "seed")
      seed_column = c;
    else if (!node_param(name))
      throw Error(header_at, "a column is a node.param (as --set takes it) or seed, not '" + name + "'");
    else
      table.keys.push_back(name);
  }
  table.has_seeds = seed_column < header.cells.size();
  for (std::size_t r = 1; r < records.size(); ++r) {
    const CsvRecord& row = records[r];
    const SourceLocation at{label, row.line, 0};
    if (row.cells.size() != header.cells.size())
      throw Error(at,
                  fmt::format("{} cell(s), but the header has {} column(s)", row.cells.size(), header.cells.size()));
    std::vector<std::string> values;
    for (std::size_t c = 0; c < row.cells.size(); ++c) {
      if (c == seed_column)
        table.seeds.push_back(parse_seed(trimmed(row.cells[c]), at));
      else
        values.push_back(trimmed(row.cells[c]));
    }
    table.values.push_back(std::move(values));
    table.lines.push_back(row.line);
  }
  if (table.values.empty()) throw Error(header_at, "no cases: the header is the last row");
  return table;
}

CaseTable read_case_table(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw Error("cannot open the cases file " + file);
  return read_case_table(in, file);
}

}  // namespace kestrel::cli
