#pragma once
// The link's peer parameters as mavlink_source and mavlink_sink declare them: which MAVLink
// system is the autopilot, whether udpin locks onto the address its heartbeat comes from, and
// how frames are signed; and the report keys that say what the link refused.
#include <kestrel/config_spec.hpp>
#include <kestrel/report_section.hpp>

#include "kestrel/mavlink/signing_param.hpp"
#include "link.hpp"

namespace kestrel::mavlink {

struct PeerConfig {
  std::int64_t autopilot_system_id = 1;
  bool pin_peer = true;
};

template <class Config>
void declare_peer(ConfigSpec<Config>& c, PeerConfig Config::*group, SigningConfig Config::*signing) {
  c.param("autopilot_system_id", group, &PeerConfig::autopilot_system_id)
      .range(1, 255)
      .describe("the autopilot's MAVLink system id: frames of other systems are ignored (and counted)");
  c.param("pin_peer", group, &PeerConfig::pin_peer)
      .describe(
          "udpin: lock onto the address the autopilot's first heartbeat comes from and hear only it while its "
          "heartbeats keep coming (another address is counted and never answered); false: answer whoever spoke "
          "last. udpout and serial links have one peer anyway");
  declare_signing(c, signing);
}

/// Throws kestrel::Error when signing is asked for and the key file cannot be used.
inline LinkOptions link_options(const PeerConfig& peer, const SigningConfig& signing, double heartbeat_timeout_s) {
  return {static_cast<std::uint8_t>(peer.autopilot_system_id), peer.pin_peer, heartbeat_timeout_s,
          make_signing(signing)};
}

/// What the link let in and kept out: foreign addresses, other systems, signatures.
inline ReportSection& report_link_guard(ReportSection& section, const VehicleView& view) {
  section.metric("foreign_datagrams", view.foreign_datagrams, "", Better::lower)
      .metric("other_system_frames", view.other_system_frames, "frames", Better::lower)
      .quantity("peer_pins", view.pins);
  return report_signing(section, view.signing, view.signatures);
}

}  // namespace kestrel::mavlink
