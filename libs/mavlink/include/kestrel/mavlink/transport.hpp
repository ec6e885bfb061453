#pragma once
// The bytes of a MAVLink link, whatever carries them: UDP or a serial port. Everything above (the
// link, the nodes, `kestrel mavlink listen`) sees only this interface, so tests run it over
// loopback sockets and pseudo-terminals.
#include <chrono>
#include <cstdint>
#include <memory>
#include <span>
#include <string>

#include "kestrel/mavlink/connection_url.hpp"

namespace kestrel::mavlink {

/// One thread may receive while another sends (a link's reader thread and its nodes).
class Transport {
 public:
  virtual ~Transport() = default;
  /// Sends one datagram (UDP) or writes the bytes (serial). False when there is nobody to send
  /// to yet (udpin before the first datagram) or the peer refused it.
  virtual bool send(std::span<const std::uint8_t> bytes) = 0;
  /// What arrived, waiting at most `timeout`; 0 bytes when nothing came. Throws kestrel::Error
  /// (io::PortLost for a serial port) when the transport is gone.
  virtual std::size_t receive(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout) = 0;
  /// Where it is connected, for messages ("udpin 0.0.0.0:14540, peer 127.0.0.1:40121").
  virtual std::string describe() const = 0;

  // A pinned peer (udpin; udpout and serial links have one peer by construction and ignore
  // these). With pinning on, nothing is sent until a peer is pinned, and once it is, only its
  // datagrams are received: others are dropped and counted, never answered.
  /// Turns pinning on: the link pins a peer once it has heard the autopilot from it.
  virtual void set_pinning(bool /*on*/) {}
  /// Pins the sender of the datagram receive() returned last.
  virtual void pin_sender() {}
  /// Forgets the pinned peer (silent too long): the next peer heard can be pinned.
  virtual void unpin() {}
  /// Datagrams dropped because they came from another address than the pinned peer.
  virtual std::uint64_t foreign_datagrams() const { return 0; }
  /// Hands foreign datagrams up (still counted, never answered) instead of dropping them, so that
  /// a signing link can judge them for its counters; last_was_foreign() tells them apart.
  virtual void set_foreign_delivery(bool /*on*/) {}
  /// Whether the datagram receive() returned last came from another address than the pinned peer.
  virtual bool last_was_foreign() const { return false; }
};

/// Opens the transport a URL names. Throws kestrel::Error naming the URL and the cause.
std::unique_ptr<Transport> open_transport(const ConnectionUrl& url);

}  // namespace kestrel::mavlink
