#pragma once
// The table of cases that `kestrel sweep --cases FILE` runs: a CSV file (csv_format.hpp) whose
// header names a node.param in each column, but for an optional `seed` column, and whose every
// other row is one case: the values its runs get with --set, an empty cell leaving that
// parameter as the graph has it.
#include <istream>
#include <string>
#include <vector>

namespace kestrel::cli {

struct CaseTable {
  std::vector<std::string> keys;                 ///< node.param per column, in file order, but seed
  std::vector<std::vector<std::string>> values;  ///< per case, one per key; "" where not set
  std::vector<int> lines;                        ///< per case, its line in the file
  bool has_seeds = false;                        ///< the file has a seed column
  std::vector<int> seeds;                        ///< per case, with a seed column: its seed (>= 1)
};

/// Reads a table of cases; `label` names the file in errors. Throws kestrel::Error with
/// file:line at a malformed table: an empty or duplicate column name, a name that is neither
/// node.param nor seed, a row whose number of cells differs from the header's, an open quote, a
/// seed that is not a whole number >= 1, or no row at all.
CaseTable read_case_table(std::istream& in, const std::string& label);
/// The same for a file; throws kestrel::Error if it cannot be opened.
CaseTable read_case_table(const std::string& file);

}  // namespace kestrel::cli
