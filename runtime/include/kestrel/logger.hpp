#pragma once
// Logging for nodes and components. Each logger prefixes its lines with the node id, so a
// message in a busy run still says where it came from.
#include <fmt/format.h>

#include <string>
#include <string_view>

namespace kestrel {

enum class LogLevel { debug, info, warn, error };

class Logger {
 public:
  explicit Logger(std::string name) : name_(std::move(name)) {}

  template <class... A>
  void debug(fmt::format_string<A...> f, A&&... a) {
    write(LogLevel::debug, fmt::format(f, std::forward<A>(a)...));
  }
  template <class... A>
  void info(fmt::format_string<A...> f, A&&... a) {
    write(LogLevel::info, fmt::format(f, std::forward<A>(a)...));
  }
  template <class... A>
  void warn(fmt::format_string<A...> f, A&&... a) {
    write(LogLevel::warn, fmt::format(f, std::forward<A>(a)...));
  }
  template <class... A>
  void error(fmt::format_string<A...> f, A&&... a) {
    write(LogLevel::error, fmt::format(f, std::forward<A>(a)...));
  }

  void write(LogLevel level, std::string_view text);
  const std::string& name() const { return name_; }

 private:
  std::string name_;
};

}  // namespace kestrel
