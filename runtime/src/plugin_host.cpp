#include "kestrel/runtime/plugin_host.hpp"

#include <dlfcn.h>
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>

#include "kestrel/abi.hpp"
#include "kestrel/plugin_abi.h"

namespace kestrel {

namespace fs = std::filesystem;

fs::path PluginHost::builtin_plugin_dir() {
  // The plugins sit beside this library: <libdir>/kestrel/plugins, in the build tree and in an
  // install alike.
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&PluginHost::builtin_plugin_dir), &info) != 0 && info.dli_fname)
    return fs::absolute(fs::path(info.dli_fname)).parent_path() / "kestrel" / "plugins";
  return {};
}

std::vector<fs::path> PluginHost::search_path(const std::vector<fs::path>& extra) {
  std::vector<fs::path> path;
  if (auto builtin = builtin_plugin_dir(); !builtin.empty()) path.push_back(builtin);
  if (const char* env = std::getenv("KESTREL_PLUGIN_PATH")) {
    std::stringstream entries(env);
    std::string entry;
    while (std::getline(entries, entry, ':'))
      if (!entry.empty()) path.emplace_back(entry);
  }
  path.insert(path.end(), extra.begin(), extra.end());
  return path;
}

void PluginHost::load_search_path(const std::vector<fs::path>& extra) {
  const auto builtin = builtin_plugin_dir();
  for (const auto& entry : search_path(extra)) {
    std::error_code ec;
    if (fs::is_regular_file(entry, ec)) {
      load(entry);
      continue;
    }
    if (!fs::is_directory(entry, ec)) {
      // The built-in folder may legitimately not exist (a framework built without plugins).
      if (entry != builtin) refuse(entry, fmt::format("plugin path {} is not a folder or a file", entry.string()));
      continue;
    }
    std::vector<fs::path> files;
    for (const auto& f : fs::directory_iterator(entry, ec))
      if (f.path().extension() == ".so") files.push_back(f.path());
    std::sort(files.begin(), files.end());  // a stable load order, whatever the file system does
    for (const auto& f : files) load(f);
  }
}

bool PluginHost::refuse(const fs::path& file, std::string message) {
  errors_.push_back(PluginError{file, std::move(message)});
  return false;
}

bool PluginHost::load(const fs::path& file) {
  std::error_code ec;
  const fs::path canonical = fs::weakly_canonical(file, ec);
  if (std::find(loaded_files_.begin(), loaded_files_.end(), canonical) != loaded_files_.end()) return true;
  const std::string name = file.string();

  // dlopen of a file that is not ELF says only "invalid ELF header"; say what it means.
  {
    std::ifstream in(file, std::ios::binary);
    std::array<char, 4> magic{};
    if (!in) return refuse(file, fmt::format("cannot read plugin {}", name));
    if (!in.read(magic.data(), magic.size()) || std::memcmp(magic.data(),
                                                            "\x7f"
                                                            "ELF",
                                                            4) != 0)
      return refuse(file, fmt::format("{} is not a shared library (no ELF header); is it a corrupt or truncated "
                                      "plugin?",
                                      name));
  }
  // RTLD_NOW: an unresolved symbol is reported here, not as a crash later. RTLD_LOCAL: plugins
  // cannot interpose on each other. RTLD_NODELETE: the code stays mapped for the life of the
  // process, so no object or message a plugin made can outlive its code.
  void* handle = dlopen(name.c_str(), RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
  if (!handle) return refuse(file, fmt::format("cannot load plugin {}: {}", name, dlerror()));

  dlerror();
  auto* entry = reinterpret_cast<kestrel_plugin_entry_fn>(dlsym(handle, KESTREL_PLUGIN_ENTRY_SYMBOL));
  if (!entry) {
    // Copied before dlclose(), which frees the text dlerror() returned.
    const char* error_text = dlerror();
    const std::string why = error_text ? error_text : "symbol not found";
    dlclose(handle);
    return refuse(file, fmt::format("{} is not a kestrel plugin: it has no {} entry point ({})", name,
                                    KESTREL_PLUGIN_ENTRY_SYMBOL, why));
  }
  const kestrel_plugin_descriptor* d = entry();
  if (!d || d->descriptor_size < sizeof(kestrel_plugin_descriptor)) {
    dlclose(handle);
    return refuse(file, fmt::format("{} has a malformed plugin descriptor", name));
  }
  const std::string theirs = d->abi_tag ? d->abi_tag : "?";
  if (d->abi_major != KESTREL_VERSION_MAJOR || theirs != KESTREL_ABI_TAG) {
    const std::string message = fmt::format(
        "refusing plugin {}: built for kestrel {} (ABI major {}, tag {}), but this is kestrel {} (ABI major {}, "
        "tag {}); rebuild the plugin against this kestrel",
        name, d->framework_version ? d->framework_version : "?", d->abi_major, theirs, KESTREL_VERSION_STRING,
        KESTREL_VERSION_MAJOR, KESTREL_ABI_TAG);
    dlclose(handle);
    return refuse(file, message);
  }

  // Register into a scratch registry first, so a plugin that fails half-way adds nothing.
  Registry scratch;
  scratch.set_current_plugin(name);
  std::array<char, 1024> error{};
  if (d->register_plugin(&scratch, error.data(), error.size()) != 0)
    return refuse(file, fmt::format("plugin {} failed to register: {}", name, error.data()));

  PluginInfo info{
      file, d->name ? d->name : "", d->version ? d->version : "", d->description ? d->description : "", {}, {}, {}};
  for (const auto& [type, _] : scratch.nodes()) {
    if (const auto* existing = registry_.find_node(type))
      return refuse(file, fmt::format("plugin {} registers node type '{}', which {} already provides", name, type,
                                      existing->plugin.empty() ? "the framework" : existing->plugin));
    info.node_types.push_back(type);
  }
  for (const auto& [key, _] : scratch.components()) {
    if (const auto it = registry_.components().find(key); it != registry_.components().end())
      return refuse(file, fmt::format("plugin {} registers component '{}', which {} already provides", name, key,
                                      it->second.plugin));
    info.components.push_back(key);
  }
  // The message types this plugin is the first to bring (its own, and those its ports use).
  for (const auto& [msg_name, m] : scratch.messages())
    if (!registry_.find_message(msg_name)) info.messages.push_back(msg_name);
  registry_.set_current_plugin(name);
  for (const auto& [msg_name, m] : scratch.messages()) registry_.add_message(m.info);
  for (const auto& [type, node] : scratch.nodes()) registry_.add_node(node.spec, node.factory);
  for (const auto& [key, c] : scratch.components()) registry_.add_component(c.kind, c.spec, c.factory);
  registry_.set_current_plugin("");
  loaded_files_.push_back(canonical);
  plugins_.push_back(std::move(info));
  return true;
}

}  // namespace kestrel
