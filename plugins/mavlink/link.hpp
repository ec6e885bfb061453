#pragma once
// One MAVLink link to one vehicle, shared by every node of the process that names its URL: the
// source and the sink of a vehicle share its socket, as the autopilot expects one peer. A reader
// thread parses what arrives and keeps the latest of each message the nodes need, with when it
// came; nodes take snapshots and send through the link.
#include <atomic>
#include <chrono>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "kestrel/mavlink/frame.hpp"
#include "kestrel/mavlink/frame_parser.hpp"
#include "kestrel/mavlink/messages.hpp"
#include "kestrel/mavlink/signing.hpp"
#include "kestrel/mavlink/transport.hpp"

namespace kestrel::mavlink {

using LinkClock = std::chrono::steady_clock;

/// The latest of what the vehicle's autopilot said. A `*_count` grows with each message of that
/// kind, so a reader can tell a new one from the one it has seen.
struct VehicleView {
  std::optional<LinkClock::time_point> heartbeat_at;
  Heartbeat heartbeat;
  std::uint64_t heartbeat_count = 0;
  std::optional<LinkClock::time_point> position_at;
  LocalPositionNed position;
  std::uint64_t position_count = 0;
  std::optional<LinkClock::time_point> attitude_at;
  AttitudeQuaternion attitude;
  std::uint64_t attitude_count = 0;
  std::optional<LinkClock::time_point> odometry_at;
  Odometry odometry;
  std::uint64_t odometry_count = 0;
  ExtendedSysState extended;
  std::uint8_t system_id = 0;     ///< the autopilot's, from its heartbeat (0 until heard)
  std::uint8_t component_id = 0;  ///< likewise
  ParserCounts parser;
  bool peer_pinned = false;               ///< udpin: locked onto the autopilot's address
  std::uint64_t pins = 0;                 ///< times a peer was pinned (again after a silence)
  std::uint64_t foreign_datagrams = 0;    ///< dropped: from another address than the pinned peer
  std::uint64_t other_system_frames = 0;  ///< ignored: from another MAVLink system than the autopilot's
  SigningMode signing = SigningMode::off;
  SigningCounts signatures;  ///< frames judged by their signature (all zero when signing is off)
};

/// Whom the link listens to.
struct LinkOptions {
  std::uint8_t autopilot_system_id = 1;  ///< frames of other systems are ignored
  /// udpin: lock onto the first address the autopilot's heartbeat comes from, and stay locked
  /// while its heartbeats keep coming (udpout and serial are pinned by construction).
  bool pin_peer = true;
  double heartbeat_timeout_s = 1.5;  ///< a pinned peer silent this long is let go
  /// MAVLink 2 signing: frames out signed, frames in judged (nullptr: off). Under `require` a
  /// peer is pinned only by a correctly signed heartbeat.
  std::shared_ptr<Signing> signing;
};

class Link {
 public:
  /// The process's link for `url`, opened on first use. Every later user must ask for the same
  /// options: a second node of the link that signs differently, or pins another system, is an
  /// Error rather than a silent first-one-wins. Throws kestrel::Error (the URL, the cause).
  static std::shared_ptr<Link> open(const std::string& url, const LinkOptions& options = {});
  /// A link over a transport of the caller's (tests).
  explicit Link(std::unique_ptr<Transport> transport, const LinkOptions& options = {});
  ~Link();
  Link(const Link&) = delete;
  Link& operator=(const Link&) = delete;

  VehicleView view() const;
  /// Acknowledgements and status texts received since the last call.
  std::vector<CommandAck> take_acks();
  std::vector<StatusText> take_texts();
  /// Sends as the companion computer: the autopilot's system id (autopilot_system_id), component 191.
  /// False when nobody can be sent to yet (udpin before the autopilot spoke) or the link failed.
  template <class M>
  bool send(const M& message) {
    std::lock_guard lock(send_mutex_);
    return send_frame(writer_.encode(message));
  }
  std::string describe() const;
  /// Why the reader stopped (the device went away), if it did.
  std::optional<std::string> failure() const;

 private:
  bool send_frame(const std::vector<std::uint8_t>& frame);
  void read_loop();
  void take(const Frame& frame);
  void keep_the_peer(LinkClock::time_point now);

  std::unique_ptr<Transport> transport_;
  LinkOptions options_;
  bool autopilot_heard_ = false;  // in the datagram just read (reader thread only)
  mutable std::mutex mutex_;      // guards what the reader writes
  VehicleView view_;
  std::deque<CommandAck> acks_;
  std::deque<StatusText> texts_;
  std::optional<std::string> failure_;
  std::mutex send_mutex_;  // taken before mutex_, never after
  FrameWriter writer_;     // guarded by send_mutex_
  std::atomic<bool> failed_{false};
  std::atomic<bool> stop_{false};
  std::thread reader_;
};

}  // namespace kestrel::mavlink
