#pragma once
// Comma-separated values as RFC 4180 has them, for the tables the CLI reads and writes: a cell
// may be double-quoted to hold commas, with "" for a quote inside it. One record per line (a
// quoted cell does not span lines); a line may end in \r\n, as spreadsheets and Python's csv
// module write it.
#include <istream>
#include <string>
#include <vector>

namespace kestrel::cli {

struct CsvRecord {
  int line = 0;  ///< 1-based, in the file
  std::vector<std::string> cells;
};

/// Every record of `in`, skipping blank lines and lines that start with '#'; `label` names the
/// file in errors. Throws kestrel::Error with file:line:column at a quote left open at the end
/// of its line or followed by anything but a comma.
std::vector<CsvRecord> read_csv(std::istream& in, const std::string& label);

/// A cell as written in a record: in quotes, its quotes doubled, if it holds a comma, a quote or
/// a line break; as it is otherwise.
std::string csv_cell(const std::string& text);

}  // namespace kestrel::cli
