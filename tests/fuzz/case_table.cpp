// Fuzz target: the table of cases of `kestrel sweep --cases` (CSV with quotes). Any bytes must
// give a well-formed table or a kestrel::Error naming the line; never a crash, undefined
// behaviour or another exception.
#include "case_table.hpp"

#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include "kestrel/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    const auto table = kestrel::cli::read_case_table(in, "fuzz.csv");
    // What was read is what sweep relies on: a case per row, a value per key, keys that name a
    // node's parameter, a seed >= 1 per case when the file has a seed column.
    if (table.values.empty() || table.values.size() != table.lines.size()) std::abort();
    for (const auto& row : table.values)
      if (row.size() != table.keys.size()) std::abort();
    for (const auto& key : table.keys)
      if (key.find('.') == std::string::npos) std::abort();
    if (table.has_seeds != !table.seeds.empty() && !table.values.empty()) std::abort();
    if (table.has_seeds && table.seeds.size() != table.values.size()) std::abort();
    for (const int seed : table.seeds)
      if (seed < 1) std::abort();
  } catch (const kestrel::Error&) {
    // a malformed table: the message names its line
  }
  return 0;
}
