#pragma once
// Finds, checks and loads plugin shared libraries into one Registry.
//
// Search order: the build's (or install's) plugin directory, then KESTREL_PLUGIN_PATH
// (colon-separated), then the graph's plugin_paths. A library that fails any check is refused
// with a message naming the file; the good ones still load. Loaded libraries stay loaded for the
// life of the process, so no object or message a plugin made can outlive its code.
#include <filesystem>
#include <string>
#include <vector>

#include "kestrel/registry.hpp"

namespace kestrel {

struct PluginInfo {
  std::filesystem::path file;
  std::string name;
  std::string version;
  std::string description;
  std::vector<std::string> node_types;
  std::vector<std::string> components;  ///< "kind/name"
  std::vector<std::string> messages;
};

struct PluginError {
  std::filesystem::path file;
  std::string message;  ///< full sentence, names the file
};

class PluginHost {
 public:
  PluginHost() = default;
  PluginHost(const PluginHost&) = delete;
  PluginHost& operator=(const PluginHost&) = delete;

  /// The directory of the plugins built or installed with this framework library.
  static std::filesystem::path builtin_plugin_dir();
  /// builtin_plugin_dir(), then KESTREL_PLUGIN_PATH's entries, then `extra`.
  static std::vector<std::filesystem::path> search_path(const std::vector<std::filesystem::path>& extra = {});

  /// Loads every *.so in each directory (a file entry is loaded directly). Missing directories
  /// in KESTREL_PLUGIN_PATH or `extra` are errors; a file already loaded is skipped.
  void load_search_path(const std::vector<std::filesystem::path>& extra = {});
  /// Loads one library. Returns false and records a PluginError if it is refused.
  bool load(const std::filesystem::path& file);

  const Registry& registry() const { return registry_; }
  Registry& registry() { return registry_; }
  const std::vector<PluginInfo>& plugins() const { return plugins_; }
  const std::vector<PluginError>& errors() const { return errors_; }

 private:
  bool refuse(const std::filesystem::path& file, std::string message);

  Registry registry_;
  std::vector<PluginInfo> plugins_;
  std::vector<PluginError> errors_;
  std::vector<std::filesystem::path> loaded_files_;  // canonical paths
};

}  // namespace kestrel
