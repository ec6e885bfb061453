#include "csv_format.hpp"

#include "kestrel/error.hpp"

namespace kestrel::cli {

namespace {

bool blank_or_comment(const std::string& line) {
  const auto first = line.find_first_not_of(" \t");
  return first == std::string::npos || line[first] == '#';
}

// The cells of one line. `where` is the line; columns in errors are 1-based.
std::vector<std::string> split_record(const std::string& line, SourceLocation where) {
  std::vector<std::string> cells;
  std::size_t i = 0;
  for (;;) {
    std::string cell;
    if (i < line.size() && line[i] == '"') {
      const std::size_t open = i++;
      for (;;) {
        if (i == line.size()) {
          where.column = static_cast<int>(open) + 1;
          throw Error(where, "unterminated quote: a quoted cell ends with \" on the same line");
        }
        if (line[i] == '"') {
          if (i + 1 < line.size() && line[i + 1] == '"') {  // "" inside quotes: one quote
            cell += '"';
            i += 2;
            continue;
          }
          ++i;
          break;
        }
        cell += line[i++];
      }
      if (i < line.size() && line[i] != ',') {
        where.column = static_cast<int>(i) + 1;
        throw Error(where, "a comma or the end of the line must follow a closing quote (\"\" is a quote inside one)");
      }
    } else {
      const auto comma = line.find(',', i);
      const std::size_t end = comma == std::string::npos ? line.size() : comma;
      cell = line.substr(i, end - i);
      i = end;
    }
    cells.push_back(std::move(cell));
    if (i == line.size()) return cells;
    ++i;  // past the comma: a cell follows, empty if the line ends here
  }
}

}  // namespace

std::vector<CsvRecord> read_csv(std::istream& in, const std::string& label) {
  std::vector<CsvRecord> records;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (blank_or_comment(line)) continue;
    records.push_back({number, split_record(line, SourceLocation{label, number, 0})});
  }
  return records;
}

std::string csv_cell(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}

}  // namespace kestrel::cli
