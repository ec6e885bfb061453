#ifndef KESTREL_PLUGIN_ABI_H
#define KESTREL_PLUGIN_ABI_H
/* The C boundary between the kestrel runtime and a plugin shared library.
 *
 * A plugin exports exactly one symbol, kestrel_plugin_descriptor_v1, returning a pointer to a
 * static descriptor. The runtime reads the plain-C fields first and refuses the plugin unless its
 * ABI major version and ABI tag equal the runtime's; only then does it call register_plugin,
 * which is where C++ types cross the boundary. The "_v1" in the symbol versions the descriptor
 * layout itself. Plugins never write this by hand: kestrel_add_plugin() generates it. */
#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct kestrel_plugin_descriptor {
  uint32_t descriptor_size;      /* sizeof(kestrel_plugin_descriptor) when built */
  uint32_t abi_major;            /* KESTREL_VERSION_MAJOR the plugin was built against */
  const char* abi_tag;           /* KESTREL_ABI_TAG the plugin was built with */
  const char* framework_version; /* KESTREL_VERSION_STRING the plugin was built against */
  const char* name;
  const char* version;
  const char* description;
  /* Adds the plugin's node types, components and messages to the registry (a kestrel::Registry*).
   * Returns 0 on success; otherwise writes a message into error (always NUL-terminated). */
  int (*register_plugin)(void* registry, char* error, size_t error_size);
} kestrel_plugin_descriptor;

typedef const kestrel_plugin_descriptor* (*kestrel_plugin_entry_fn)(void);

#define KESTREL_PLUGIN_ENTRY_SYMBOL "kestrel_plugin_descriptor_v1"

#ifdef __cplusplus
}
#endif

#endif /* KESTREL_PLUGIN_ABI_H */
