#pragma once
// Registration macros for plugin authors: one macro per node type, component or message type.
//
//   KESTREL_REGISTER_NODE(VoxelFilter)
//   KESTREL_REGISTER_COMPONENT(Associator, HungarianAssociator)
//   KESTREL_REGISTER_MESSAGE(my::Message)
//
// The macros record into a list private to the plugin's shared library; the generated entry
// point (see kestrel_add_plugin in CMake) hands the list to the runtime after the ABI handshake.
#include <cstdio>
#include <functional>
#include <memory>
#include <vector>

#include "kestrel/abi.hpp"
#include "kestrel/node.hpp"
#include "kestrel/plugin_abi.h"
#include "kestrel/registry.hpp"

namespace kestrel::detail {

using Registration = std::function<void(Registry&)>;

// Hidden visibility keeps one list per shared library, even though every plugin defines it.
[[gnu::visibility("hidden")]] inline std::vector<Registration>& plugin_registrations() {
  static std::vector<Registration> list;
  return list;
}

[[gnu::visibility("hidden")]] inline bool add_registration(Registration r) {
  plugin_registrations().push_back(std::move(r));
  return true;
}

template <class N>
void register_node(Registry& r) {
  r.add_node(N::spec(), [](NodeInit& init) -> std::unique_ptr<Node> { return std::make_unique<N>(init); });
}

template <class Interface, class C>
void register_component(Registry& r) {
  static_assert(std::is_base_of_v<Interface, C>, "a component must derive from its interface");
  r.add_component(std::string(Interface::kKind), C::spec(), [](const ComponentInit& init) -> std::shared_ptr<void> {
    std::shared_ptr<Interface> as_interface;
    if constexpr (std::is_constructible_v<C, const ComponentInit&>)
      as_interface = std::make_shared<C>(init);
    else
      as_interface = std::make_shared<C>(init.params());  // a component that needs only its parameters
    return std::static_pointer_cast<void>(as_interface);
  });
}

}  // namespace kestrel::detail

#define KESTREL_CONCAT_IMPL(a, b) a##b
#define KESTREL_CONCAT(a, b) KESTREL_CONCAT_IMPL(a, b)

#define KESTREL_REGISTER_NODE(NODE_CLASS)                                                 \
  namespace {                                                                             \
  [[maybe_unused]] const bool KESTREL_CONCAT(kestrel_registered_node_, __COUNTER__) =     \
      ::kestrel::detail::add_registration(&::kestrel::detail::register_node<NODE_CLASS>); \
  }

#define KESTREL_REGISTER_COMPONENT(INTERFACE, COMPONENT_CLASS)                                                 \
  namespace {                                                                                                  \
  [[maybe_unused]] const bool KESTREL_CONCAT(kestrel_registered_component_, __COUNTER__) =                     \
      ::kestrel::detail::add_registration(&::kestrel::detail::register_component<INTERFACE, COMPONENT_CLASS>); \
  }

#define KESTREL_REGISTER_MESSAGE(MESSAGE_TYPE)                                                            \
  namespace {                                                                                             \
  [[maybe_unused]] const bool KESTREL_CONCAT(kestrel_registered_message_, __COUNTER__) =                  \
      ::kestrel::detail::add_registration([](::kestrel::Registry& r) { r.add_message<MESSAGE_TYPE>(); }); \
  }

/// The plugin's C entry point. Generated once per plugin by kestrel_add_plugin(); never written
/// by hand.
#define KESTREL_PLUGIN_ENTRY(NAME, VERSION, DESCRIPTION)                                                           \
  namespace {                                                                                                      \
  int kestrel_register_plugin(void* registry, char* error, size_t error_size) {                                    \
    try {                                                                                                          \
      for (auto& registration : ::kestrel::detail::plugin_registrations())                                         \
        registration(*static_cast<::kestrel::Registry*>(registry));                                                \
      return 0;                                                                                                    \
    } catch (const std::exception& e) {                                                                            \
      if (error_size > 0) {                                                                                        \
        std::snprintf(error, error_size, "%s", e.what());                                                          \
      }                                                                                                            \
      return 1;                                                                                                    \
    }                                                                                                              \
  }                                                                                                                \
  const kestrel_plugin_descriptor kestrel_descriptor = {sizeof(kestrel_plugin_descriptor),                         \
                                                        KESTREL_VERSION_MAJOR,                                     \
                                                        KESTREL_ABI_TAG,                                           \
                                                        KESTREL_VERSION_STRING,                                    \
                                                        NAME,                                                      \
                                                        VERSION,                                                   \
                                                        DESCRIPTION,                                               \
                                                        &kestrel_register_plugin};                                 \
  }                                                                                                                \
  extern "C" __attribute__((visibility("default"))) const kestrel_plugin_descriptor* kestrel_plugin_descriptor_v1( \
      void) {                                                                                                      \
    return &kestrel_descriptor;                                                                                    \
  }
