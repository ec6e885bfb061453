#pragma once
// Writing the CLI's output files with every step checked. A file that cannot be written is an
// error that names it (exit code 1), never a silent loss.
#include <filesystem>
#include <string>
#include <vector>

#include "kestrel/plot/line_plot.hpp"

namespace kestrel::cli {

/// Creates the folder and its parents.
void make_folder(const std::filesystem::path& dir);

/// Writes the whole text to the file: open, write and close are each checked.
void write_file(const std::filesystem::path& file, const std::string& text);

/// plot::save_png, failing the same way as write_file.
void write_png(const std::filesystem::path& file, const std::vector<plot::Panel>& panels, int width, int panel_height);

}  // namespace kestrel::cli
