#include "kestrel/node_spec.hpp"

namespace kestrel {

namespace {
int index_of(const std::vector<PortSpec>& ports, std::string_view name) {
  for (std::size_t i = 0; i < ports.size(); ++i)
    if (ports[i].name == name) return static_cast<int>(i);
  return -1;
}
}  // namespace

int NodeSpec::input_index(std::string_view name) const { return index_of(inputs_, name); }
int NodeSpec::output_index(std::string_view name) const { return index_of(outputs_, name); }

}  // namespace kestrel
