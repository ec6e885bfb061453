#include "kestrel/logger.hpp"

#include <spdlog/spdlog.h>

namespace kestrel {

void Logger::write(LogLevel level, std::string_view text) {
  switch (level) {
    case LogLevel::debug:
      spdlog::debug("[{}] {}", name_, text);
      break;
    case LogLevel::info:
      spdlog::info("[{}] {}", name_, text);
      break;
    case LogLevel::warn:
      spdlog::warn("[{}] {}", name_, text);
      break;
    case LogLevel::error:
      spdlog::error("[{}] {}", name_, text);
      break;
  }
}

}  // namespace kestrel
