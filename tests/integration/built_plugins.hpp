#pragma once
// The in-tree plugins, loaded once per test program from the build's plugin folder. The host is
// never destroyed: plugins are never unloaded, and nodes they made may outlive a test.
#include "kestrel/runtime/plugin_host.hpp"

namespace kestrel::testing {

inline PluginHost& built_plugins() {
  static PluginHost* host = [] {
    auto* h = new PluginHost();
    h->load_search_path();
    return h;
  }();
  return *host;
}

}  // namespace kestrel::testing
