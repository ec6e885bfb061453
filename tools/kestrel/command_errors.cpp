#include "command_errors.hpp"

#include <cstdio>
#include <exception>

namespace kestrel::cli {

int run_command_body(const char* name, const std::function<int()>& body) {
  try {
    return body();
  } catch (const CommandError& e) {
    std::fprintf(stderr, "kestrel %s: %s\n", name, e.what());
    return e.code();
  } catch (const Error& e) {
    std::fprintf(stderr, "kestrel %s: %s\n", name, e.what());
    return kUsage;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "kestrel %s: %s\n", name, e.what());
    return kRunFailed;
  }
}

}  // namespace kestrel::cli
