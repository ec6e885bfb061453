#pragma once
// The quality of service a kestrel topic is written and read with: ROS 2's profile of three
// policies. The defaults are ROS 2's ("reliable, keep last 10, volatile"), so that a ROS 2 node
// with its default QoS matches every kestrel topic.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace kestrel::dds {

enum class Reliability { reliable, best_effort };
enum class Durability { volatile_, transient_local };

struct Qos {
  Reliability reliability = Reliability::reliable;
  std::int32_t depth = 10;  ///< keep last this many samples
  Durability durability = Durability::volatile_;

  bool operator==(const Qos&) const = default;
};

/// "reliable, keep last 10, volatile".
std::string to_string(const Qos& qos);

/// `base` changed by the words of `spec`, separated by spaces or commas: reliable, best_effort,
/// volatile, transient_local, depth=N (1 to 100000). Throws kestrel::Error naming a word it does
/// not know.
Qos parse_qos(std::string_view spec, Qos base);

/// Per-topic QoS: the defaults, and overrides "PATTERN: WORDS; PATTERN: WORDS" (entries separated by
/// ';' or new lines; patterns are globs on the ROS 2 topic name, '*' crossing '/', the last
/// matching entry winning), as ROS 2's qos_overrides set them per topic.
class QosTable {
 public:
  QosTable() = default;
  /// Throws kestrel::Error for an entry without ':' or with words parse_qos() refuses.
  QosTable(Qos defaults, std::string_view overrides);

  Qos for_topic(std::string_view ros_topic) const;

 private:
  struct Entry {
    std::string pattern;
    std::string words;
  };
  Qos defaults_;
  std::vector<Entry> entries_;
};

}  // namespace kestrel::dds
