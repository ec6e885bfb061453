#include "kestrel/dds/qos.hpp"

#include <fmt/format.h>
#include <fnmatch.h>

#include <charconv>
#include <kestrel/error.hpp>

namespace kestrel::dds {
namespace {

std::string_view trim(std::string_view s) {
  const auto begin = s.find_first_not_of(" \t\r\n");
  if (begin == std::string_view::npos) return {};
  const auto end = s.find_last_not_of(" \t\r\n");
  return s.substr(begin, end - begin + 1);
}

}  // namespace

std::string to_string(const Qos& qos) {
  return fmt::format("{}, keep last {}, {}", qos.reliability == Reliability::reliable ? "reliable" : "best effort",
                     qos.depth, qos.durability == Durability::volatile_ ? "volatile" : "transient local");
}

Qos parse_qos(std::string_view spec, Qos base) {
  std::size_t pos = 0;
  while (pos < spec.size()) {
    const auto end = spec.find_first_of(" ,\t", pos);
    const std::string_view word = spec.substr(pos, end == std::string_view::npos ? spec.npos : end - pos);
    pos = end == std::string_view::npos ? spec.size() : end + 1;
    if (word.empty()) continue;
    if (word == "reliable") {
      base.reliability = Reliability::reliable;
    } else if (word == "best_effort") {
      base.reliability = Reliability::best_effort;
    } else if (word == "volatile") {
      base.durability = Durability::volatile_;
    } else if (word == "transient_local") {
      base.durability = Durability::transient_local;
    } else if (word.starts_with("depth=")) {
      const std::string_view number = word.substr(6);
      std::int32_t depth = 0;
      const auto [end_of_number, ec] = std::from_chars(number.data(), number.data() + number.size(), depth);
      if (ec != std::errc() || end_of_number != number.data() + number.size() || depth < 1 || depth > 100000)
        throw Error(fmt::format("QoS '{}': depth must be a whole number from 1 to 100000", word));
      base.depth = depth;
    } else {
      throw Error(
          fmt::format("QoS word '{}' is not one of reliable, best_effort, volatile, transient_local, depth=N", word));
    }
  }
  return base;
}

QosTable::QosTable(Qos defaults, std::string_view overrides) : defaults_(defaults) {
  std::size_t pos = 0;
  while (pos < overrides.size()) {
    const auto end = overrides.find_first_of(";\n", pos);
    const std::string_view entry =
        trim(overrides.substr(pos, end == std::string_view::npos ? overrides.npos : end - pos));
    pos = end == std::string_view::npos ? overrides.size() : end + 1;
    if (entry.empty()) continue;
    const auto colon = entry.find(':');
    if (colon == std::string_view::npos || trim(entry.substr(0, colon)).empty())
      throw Error(fmt::format("QoS override '{}' is not 'TOPIC_PATTERN: WORDS'", entry));
    Entry e{std::string(trim(entry.substr(0, colon))), std::string(trim(entry.substr(colon + 1)))};
    parse_qos(e.words, defaults_);  // refuse a bad word now, not when the topic appears
    entries_.push_back(std::move(e));
  }
}

Qos QosTable::for_topic(std::string_view ros_topic) const {
  Qos qos = defaults_;
  const std::string topic(ros_topic);
  for (const Entry& e : entries_)
    if (fnmatch(e.pattern.c_str(), topic.c_str(), 0) == 0) qos = parse_qos(e.words, qos);
  return qos;
}

}  // namespace kestrel::dds
