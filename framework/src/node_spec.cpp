#include "kestrel/node_spec.hpp"

namespace kestrel {

namespace {
int index_of(const std::vector<PortSpec>& ports, std::string_view name) {
  for (std::size_t i = 0; i < ports.size(); ++i)
    if (ports[i].name == name) return static_cast<int>(i);
  return -1;
}
const ParamSpec* find(const std::vector<ParamSpec>& params, std::string_view name) {
  for (const auto& p : params)
    if (p.name == name) return &p;
  return nullptr;
}
}  // namespace

int NodeSpec::input_index(std::string_view name) const { return index_of(inputs_, name); }
int NodeSpec::output_index(std::string_view name) const { return index_of(outputs_, name); }
const ParamSpec* NodeSpec::find_param(std::string_view name) const { return find(params_, name); }
const ParamSpec* ComponentSpec::find_param(std::string_view name) const { return find(params_, name); }

}  // namespace kestrel
