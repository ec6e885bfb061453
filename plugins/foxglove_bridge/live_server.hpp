#pragma once
// A Foxglove WebSocket server (foxglove.websocket.v1) on Boost.Beast, with one I/O thread of its
// own. The graph's thread adds channels and publishes; it never waits for a client: each client
// has a bounded SendQueue that drops its oldest data when the client reads too slowly. Clients
// connect, subscribe, unsubscribe and leave at any moment.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "protocol.hpp"

namespace kestrel::foxglove {

struct LiveServerOptions {
  std::string address = "127.0.0.1";
  std::uint16_t port = 8765;  ///< 0: any free port (port() tells which)
  std::size_t client_queue_bytes = 16u << 20;
  std::string name = "kestrel";  ///< serverInfo's name
};

struct LiveServerStats {
  std::uint64_t clients = 0;  ///< that completed the handshake, over the run
  std::uint64_t max_clients = 0;
  std::uint64_t rejected = 0;  ///< connections that were not foxglove.websocket.v1 WebSockets
  std::uint64_t messages_sent = 0;
  std::uint64_t bytes_sent = 0;
  std::uint64_t dropped = 0;  ///< data frames dropped from slow clients' queues
  double io_cpu_s = 0.0;      ///< CPU time of the server's I/O thread so far (framing and sending)
};

class LiveServer {
 public:
  /// Listens at once; throws kestrel::Error naming the address and port when it cannot.
  explicit LiveServer(const LiveServerOptions& options);
  ~LiveServer();
  LiveServer(const LiveServer&) = delete;
  LiveServer& operator=(const LiveServer&) = delete;

  std::uint16_t port() const;
  /// Adds a channel (its id is chosen here and returned) and advertises it to every client.
  std::uint32_t add_channel(Channel channel);
  /// Whether some client subscribes to `channel_id`: the caller skips encoding when none does.
  bool subscribed(std::uint32_t channel_id) const;
  /// Sends a message to every client subscribed to `channel_id`.
  void publish(std::uint32_t channel_id, std::uint64_t time_ns,
               std::shared_ptr<const std::vector<std::uint8_t>> payload);
  /// Sends the server's time to every client (the `time` capability).
  void publish_time(std::uint64_t time_ns);
  /// Closes every connection (waiting at most a second for clients to answer) and the I/O thread.
  void stop();
  LiveServerStats stats() const;

  struct Impl;  // Beast stays out of this header; public only so that live_server.cpp's sessions see it

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace kestrel::foxglove
