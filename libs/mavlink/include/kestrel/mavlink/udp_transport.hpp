#pragma once
// MAVLink over UDP, one frame or more per datagram. udpin binds its port and answers whoever
// sent the last datagram (PX4 SITL and MAVSDK pair this way), or, with pinning on, only the peer
// the link pinned; udpout sends to a fixed address from an ephemeral port and hears the replies
// there.
#include <netinet/in.h>

#include <atomic>
#include <mutex>

#include "kestrel/mavlink/transport.hpp"

namespace kestrel::mavlink {

class UdpTransport : public Transport {
 public:
  /// Throws kestrel::Error when the address does not resolve or the port is taken.
  explicit UdpTransport(const ConnectionUrl& url);
  ~UdpTransport() override;
  UdpTransport(const UdpTransport&) = delete;
  UdpTransport& operator=(const UdpTransport&) = delete;

  bool send(std::span<const std::uint8_t> bytes) override;
  std::size_t receive(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout) override;
  std::string describe() const override;
  void set_pinning(bool on) override;
  void pin_sender() override;
  void unpin() override;
  std::uint64_t foreign_datagrams() const override { return foreign_; }
  void set_foreign_delivery(bool on) override;
  bool last_was_foreign() const override;
  /// The local port bound (useful when the URL asked for an ephemeral one).
  std::uint16_t local_port() const;

 private:
  ConnectionUrl url_;
  int fd_ = -1;
  mutable std::mutex peer_mutex_;  // the receiving thread learns the peer the sending one uses
  bool have_peer_ = false;
  sockaddr_in peer_{};
  bool pinning_ = false, pinned_ = false;
  bool deliver_foreign_ = false, last_foreign_ = false;
  sockaddr_in last_from_{};  // the sender of the datagram receive() returned last
  std::atomic<std::uint64_t> foreign_{0};
};

}  // namespace kestrel::mavlink
