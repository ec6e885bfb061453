#pragma once
// The ABI tag: what must match between the runtime and a plugin for C++ objects to cross
// between them safely. It combines the C++ standard, the standard library's ABI and a hash of
// the public headers the plugin was compiled against, so a plugin built against other headers
// is refused instead of crashing.
#include <cstddef>  // defines _GLIBCXX_USE_CXX11_ABI

#include "kestrel/version.hpp"

#define KESTREL_STRINGIFY_IMPL(x) #x
#define KESTREL_STRINGIFY(x) KESTREL_STRINGIFY_IMPL(x)

#if defined(_GLIBCXX_USE_CXX11_ABI)
#define KESTREL_STDLIB_TAG "libstdc++-cxx11abi" KESTREL_STRINGIFY(_GLIBCXX_USE_CXX11_ABI)
#elif defined(_LIBCPP_VERSION)
#define KESTREL_STDLIB_TAG "libc++"
#else
#define KESTREL_STDLIB_TAG "unknown-stdlib"
#endif

#define KESTREL_ABI_TAG \
  "c++" KESTREL_STRINGIFY(__cplusplus) "/" KESTREL_STDLIB_TAG "/abi-" KESTREL_ABI_VERSION "/api-" KESTREL_API_HASH
