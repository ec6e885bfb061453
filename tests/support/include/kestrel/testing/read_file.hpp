#pragma once
// A whole file as a string, for tests that check what a run wrote; empty if it cannot be read.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace kestrel::testing {

inline std::string read_file(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace kestrel::testing
