#pragma once
// The link's peer parameters as mavlink_source and mavlink_sink declare them: which MAVLink
// system is the autopilot, and whether udpin locks onto the address its heartbeat comes from.
#include <kestrel/config_spec.hpp>

#include "link.hpp"

namespace kestrel::mavlink {

struct PeerConfig {
  std::int64_t autopilot_system_id = 1;
  bool pin_peer = true;
};

template <class Config>
void declare_peer(ConfigSpec<Config>& c, PeerConfig Config::*group) {
  c.param("autopilot_system_id", group, &PeerConfig::autopilot_system_id)
      .range(1, 255)
      .describe("the autopilot's MAVLink system id: frames of other systems are ignored (and counted)");
  c.param("pin_peer", group, &PeerConfig::pin_peer)
      .describe(
          "udpin: lock onto the address the autopilot's first heartbeat comes from and hear only it while its "
          "heartbeats keep coming (another address is counted and never answered); false: answer whoever spoke "
          "last. udpout and serial links have one peer anyway");
}

inline LinkOptions link_options(const PeerConfig& peer, double heartbeat_timeout_s) {
  return {static_cast<std::uint8_t>(peer.autopilot_system_id), peer.pin_peer, heartbeat_timeout_s};
}

}  // namespace kestrel::mavlink
