#pragma once
// A place in the temporary folder for one test's files. CTest runs the tests of one executable as
// separate processes in parallel, so a fixed name would let one test remove or overwrite another's
// files; the process id keeps them apart. The extension is kept, so "plot.png" stays a PNG name.
#include <unistd.h>

#include <filesystem>
#include <string>

namespace kestrel::testing {

inline std::filesystem::path scratch_path(const std::string& name) {
  const std::filesystem::path p(name);
  return std::filesystem::temp_directory_path() /
         (p.stem().string() + "-" + std::to_string(::getpid()) + p.extension().string());
}

}  // namespace kestrel::testing
