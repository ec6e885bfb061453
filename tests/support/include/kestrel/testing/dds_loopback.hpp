#pragma once
// DDS for tests: Cyclone on the loopback interface only, unicast discovery to 127.0.0.1, and a
// domain of the test process's own, so that tests running at once never see each other's topics
// and nothing leaves the machine.
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <string>

namespace kestrel::testing {

/// Cyclone's configuration for loopback (docs/ros2.md has the same, for users).
inline const char* dds_loopback_config() {
  return "<CycloneDDS><Domain id=\"any\"><General><Interfaces><NetworkInterface name=\"lo\"/></Interfaces>"
         "<AllowMulticast>false</AllowMulticast></General><Discovery><ParticipantIndex>auto</ParticipantIndex>"
         "<MaxAutoParticipantIndex>20</MaxAutoParticipantIndex><Peers><Peer address=\"127.0.0.1\"/></Peers>"
         "</Discovery></Domain></CycloneDDS>";
}

/// Sets CYCLONEDDS_URI for this process and the commands it starts (before the first participant);
/// returns the domain id this process uses (1 to 200, from its pid).
inline std::uint32_t use_dds_loopback() {
  ::setenv("CYCLONEDDS_URI", dds_loopback_config(), 1);
  return 1 + static_cast<std::uint32_t>(::getpid()) % 200;
}

}  // namespace kestrel::testing
