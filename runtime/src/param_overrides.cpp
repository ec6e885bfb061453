#include "param_overrides.hpp"

namespace kestrel {

void add_command_line_overrides(const std::vector<std::string>& texts, Overrides& out, Diagnostics& diag) {
  for (const auto& text : texts) {
    const SourceLocation where{"--set " + text, 0, 0};
    const auto eq = text.find('=');
    const auto dot = text.find('.');
    if (eq == std::string::npos || dot == std::string::npos || dot > eq || dot == 0 || dot + 1 == eq) {
      diag.error(where, "expected --set node.param=value");
      continue;
    }
    const std::string node = text.substr(0, dot);
    const std::string param = text.substr(dot + 1, eq - dot - 1);
    YAML::Node value;
    try {
      value = YAML::Load(text.substr(eq + 1));
    } catch (const YAML::Exception& e) {
      diag.error(where, "the value is not valid YAML: " + e.msg);
      continue;
    }
    if (value.IsNull() && text.substr(eq + 1).empty()) {
      diag.error(where, "no value after '='");
      continue;
    }
    out[node][param] = Override{value, where};
  }
}

void add_include_overrides(const GraphSource::Impl& file, Overrides& out, Diagnostics& diag) {
  for (const auto& include : file.includes) {
    if (!include.set) continue;
    for (auto it = include.set.begin(); it != include.set.end(); ++it) {
      const std::string key = it->first.Scalar();
      const auto dot = key.find('.');
      if (dot == std::string::npos || dot == 0 || dot + 1 == key.size()) {
        diag.error(file.at(it->first), "an include's 'set' key is node.param, not '" + key + "'");
        continue;
      }
      out[key.substr(0, dot)].emplace(key.substr(dot + 1), Override{it->second, file.at(it->first)});
    }
  }
  for (const auto& include : file.includes) add_include_overrides(*include.source, out, diag);
}

}  // namespace kestrel
