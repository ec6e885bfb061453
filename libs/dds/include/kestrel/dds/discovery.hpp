#pragma once
// What the domain holds: every writer and reader other participants (and this process's other
// participants) announce, from DDS's built-in discovery topics. `kestrel dds list` prints it,
// `kestrel dds echo` finds a topic's type in it.
#include <chrono>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "kestrel/dds/participant.hpp"
#include "kestrel/dds/qos.hpp"
#include "kestrel/dds/writer.hpp"

namespace kestrel::dds {

struct DiscoveredEndpoint {
  std::string dds_topic;  ///< "rt/camera/frame/left"
  std::string dds_type;   ///< "sensor_msgs::msg::dds_::Image_"
  bool writer = true;     ///< a writer (publisher), or a reader (subscriber)
  Qos qos;
  std::string participant;  ///< its participant's GUID prefix, as hex
  WriterMetadata metadata;  ///< its USER_DATA
};

class Discovery {
 public:
  explicit Discovery(const Participant& participant);
  ~Discovery();
  Discovery(const Discovery&) = delete;
  Discovery& operator=(const Discovery&) = delete;

  /// The endpoints alive now, the participant's own left out, sorted by topic.
  std::vector<DiscoveredEndpoint> endpoints();
  /// Polls until `until` says yes or `timeout` passes; returns the last endpoints.
  std::vector<DiscoveredEndpoint> wait(std::chrono::milliseconds timeout,
                                       const std::function<bool(const std::vector<DiscoveredEndpoint>&)>& until);

 private:
  void poll(std::int32_t reader, bool writers);

  std::string own_guid_;
  std::int32_t publications_ = 0, subscriptions_ = 0;
  std::map<std::string, DiscoveredEndpoint> alive_;  // by endpoint GUID
};

}  // namespace kestrel::dds
