#pragma once
// A DDS domain participant (Eclipse Cyclone DDS): what every writer, reader and discovery of one
// process hangs from. Cyclone reads its network settings from CYCLONEDDS_URI, as ROS 2's
// rmw_cyclonedds_cpp does (docs/ros2.md: loopback only, peers, interfaces).
#include <cstdint>
#include <memory>
#include <string>

namespace kestrel::dds {

class Participant {
 public:
  /// Joins `domain_id` (0 to 232, ROS_DOMAIN_ID's range). Throws kestrel::Error with Cyclone's reason.
  explicit Participant(std::uint32_t domain_id);
  ~Participant();
  Participant(const Participant&) = delete;
  Participant& operator=(const Participant&) = delete;

  std::uint32_t domain_id() const { return domain_id_; }
  /// Cyclone's entity handle (dds_entity_t), for this library's writers and readers.
  std::int32_t entity() const { return entity_; }
  /// This participant's GUID prefix as hex, to tell its own endpoints from others in discovery.
  const std::string& guid() const { return guid_; }

 private:
  std::uint32_t domain_id_;
  std::int32_t entity_;
  std::string guid_;
};

}  // namespace kestrel::dds
