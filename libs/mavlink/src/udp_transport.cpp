#include "kestrel/mavlink/udp_transport.hpp"

#include <arpa/inet.h>
#include <netdb.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <kestrel/error.hpp>

namespace kestrel::mavlink {

namespace {

sockaddr_in resolve(const std::string& host, std::uint16_t port, const std::string& url) {
  addrinfo hints{};
  hints.ai_family = AF_INET;
  hints.ai_socktype = SOCK_DGRAM;
  addrinfo* found = nullptr;
  const int rc = ::getaddrinfo(host.c_str(), nullptr, &hints, &found);
  if (rc != 0 || found == nullptr)
    throw Error("connection '" + url + "': cannot resolve '" + host + "': " + gai_strerror(rc));
  sockaddr_in address{};
  std::memcpy(&address, found->ai_addr, sizeof address);
  ::freeaddrinfo(found);
  address.sin_port = htons(port);
  return address;
}

bool same_address(const sockaddr_in& a, const sockaddr_in& b) {
  return a.sin_addr.s_addr == b.sin_addr.s_addr && a.sin_port == b.sin_port;
}

std::string text_of(const sockaddr_in& a) {
  char host[INET_ADDRSTRLEN] = {};
  ::inet_ntop(AF_INET, &a.sin_addr, host, sizeof host);
  return std::string(host) + ":" + std::to_string(ntohs(a.sin_port));
}

}  // namespace

UdpTransport::UdpTransport(const ConnectionUrl& url) : url_(url) {
  fd_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  if (fd_ < 0) throw Error("connection '" + url.text + "': socket: " + std::strerror(errno));
  sockaddr_in local{};
  local.sin_family = AF_INET;
  if (url.kind == ConnectionUrl::Kind::udp_in) {
    local = resolve(url.host, url.port, url.text);
  } else {
    local.sin_addr.s_addr = htonl(INADDR_ANY);
    local.sin_port = 0;
    peer_ = resolve(url.host, url.port, url.text);
    have_peer_ = true;
  }
  if (::bind(fd_, reinterpret_cast<const sockaddr*>(&local), sizeof local) != 0) {
    const int e = errno;
    ::close(fd_);
    throw Error("connection '" + url.text + "': cannot listen on " + text_of(local) + ": " + std::strerror(e) +
                (e == EADDRINUSE ? " (another program, or another link, has the port)" : ""));
  }
}

UdpTransport::~UdpTransport() {
  if (fd_ >= 0) ::close(fd_);
}

bool UdpTransport::send(std::span<const std::uint8_t> bytes) {
  sockaddr_in peer{};
  {
    std::lock_guard lock(peer_mutex_);
    if (!have_peer_) return false;
    peer = peer_;
  }
  const ssize_t n =
      ::sendto(fd_, bytes.data(), bytes.size(), MSG_NOSIGNAL, reinterpret_cast<const sockaddr*>(&peer), sizeof peer);
  // ECONNREFUSED: the last datagram bounced (nobody listens there yet); the next may not.
  return n == static_cast<ssize_t>(bytes.size());
}

std::size_t UdpTransport::receive(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout) {
  pollfd p{fd_, POLLIN, 0};
  for (;;) {
    const int ready = ::poll(&p, 1, static_cast<int>(timeout.count()));
    if (ready < 0 && errno == EINTR) continue;
    if (ready < 0) throw Error("connection '" + url_.text + "': poll: " + std::strerror(errno));
    if (ready == 0) return 0;
    sockaddr_in from{};
    socklen_t from_size = sizeof from;
    const ssize_t n = ::recvfrom(fd_, buffer.data(), buffer.size(), 0, reinterpret_cast<sockaddr*>(&from), &from_size);
    if (n < 0) {
      if (errno == EINTR || errno == EAGAIN || errno == ECONNREFUSED) return 0;
      throw Error("connection '" + url_.text + "': receive: " + std::strerror(errno));
    }
    if (url_.kind == ConnectionUrl::Kind::udp_in) {
      std::lock_guard lock(peer_mutex_);
      last_foreign_ = pinned_ && !same_address(from, peer_);
      if (last_foreign_) {
        ++foreign_;  // not the pinned autopilot: never answered, and dropped unless asked for
        if (deliver_foreign_) return static_cast<std::size_t>(n);
        last_foreign_ = false;
        continue;
      }
      last_from_ = from;
      if (!pinning_) {
        peer_ = from;
        have_peer_ = true;
      }
    }
    return static_cast<std::size_t>(n);
  }
}

std::string UdpTransport::describe() const {
  std::string text =
      (url_.kind == ConnectionUrl::Kind::udp_in ? "udpin " : "udpout ") + url_.host + ":" + std::to_string(url_.port);
  std::lock_guard lock(peer_mutex_);
  if (have_peer_) text += ", peer " + text_of(peer_) + (pinned_ ? " (pinned)" : "");
  if (foreign_ > 0) text += ", " + std::to_string(foreign_) + " datagram(s) from elsewhere dropped";
  return text;
}

void UdpTransport::set_pinning(bool on) {
  if (url_.kind != ConnectionUrl::Kind::udp_in) return;  // udpout has its one peer already
  std::lock_guard lock(peer_mutex_);
  pinning_ = on;
  if (on && !pinned_) have_peer_ = false;  // nobody is answered before the autopilot is heard
}

void UdpTransport::pin_sender() {
  if (url_.kind != ConnectionUrl::Kind::udp_in) return;
  std::lock_guard lock(peer_mutex_);
  peer_ = last_from_;
  have_peer_ = pinned_ = true;
}

void UdpTransport::unpin() {
  if (url_.kind != ConnectionUrl::Kind::udp_in) return;
  std::lock_guard lock(peer_mutex_);
  pinned_ = false;
  if (pinning_) have_peer_ = false;
}

void UdpTransport::set_foreign_delivery(bool on) {
  std::lock_guard lock(peer_mutex_);
  deliver_foreign_ = on;
}

bool UdpTransport::last_was_foreign() const {
  std::lock_guard lock(peer_mutex_);
  return last_foreign_;
}

std::uint16_t UdpTransport::local_port() const {
  sockaddr_in local{};
  socklen_t size = sizeof local;
  ::getsockname(fd_, reinterpret_cast<sockaddr*>(&local), &size);
  return ntohs(local.sin_port);
}

}  // namespace kestrel::mavlink
