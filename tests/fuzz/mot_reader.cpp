// Fuzz target: `kestrel mot`'s MOTChallenge reader. Any bytes must give frames of rows or a
// kestrel::Error naming the line; never a crash, undefined behaviour or another exception.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include "kestrel/error.hpp"
#include "mot_files.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  for (const bool ground_truth : {true, false}) {
    std::istringstream in(text);
    try {
      const auto frames = kestrel::cli::read_mot(in, "fuzz.txt", ground_truth);
      for (const auto& [frame, rows] : frames)
        for (const auto& row : rows) {
          // What was read is usable by the metrics: finite numbers only.
          if (!std::isfinite(row.left) || !std::isfinite(row.top) || !std::isfinite(row.width) ||
              !std::isfinite(row.height) || !std::isfinite(row.conf) || !row.point.allFinite())
            std::abort();
          if (ground_truth && row.conf == 0) std::abort();
        }
    } catch (const kestrel::Error&) {
      // a malformed file: the message names its line
    }
  }
  return 0;
}
