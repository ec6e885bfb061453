#include "kestrel/tracking/deprecated_tracker.hpp"

#include <mutex>
#include <set>
#include <string>

namespace kestrel::tracking {

void warn_deprecated(Logger& log, std::string_view type, std::string_view replacement) {
  static std::mutex mutex;
  static std::set<std::string, std::less<>> warned;
  const std::lock_guard<std::mutex> lock(mutex);
  if (!warned.emplace(type).second) return;
  log.warn("node type '{}' is deprecated and will be removed in the next release; use {} (see CHANGELOG.md)", type,
           replacement);
}

}  // namespace kestrel::tracking
