#include "output_files.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "command_errors.hpp"

namespace kestrel::cli {

namespace {

[[noreturn]] void fail(const std::filesystem::path& file, int error) {
  throw CommandError(kRunFailed, "cannot write " + file.string() + ": " + std::strerror(error));
}

}  // namespace

void make_folder(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw CommandError(kRunFailed, "cannot create the folder " + dir.string() + ": " + ec.message());
}

void write_file(const std::filesystem::path& file, const std::string& text) {
  std::FILE* out = std::fopen(file.c_str(), "wb");
  if (!out) fail(file, errno);
  const bool written = std::fwrite(text.data(), 1, text.size(), out) == text.size();
  const int write_error = errno;
  // Buffered data reaches the file at fclose: a full disk shows up there.
  if (std::fclose(out) != 0) fail(file, errno);
  if (!written) fail(file, write_error);
}

void write_png(const std::filesystem::path& file, const std::vector<plot::Panel>& panels, int width, int panel_height) {
  try {
    plot::save_png(file, panels, width, panel_height);
  } catch (const Error& e) {
    throw CommandError(kRunFailed, e.what());
  }
}

}  // namespace kestrel::cli
