#include "live_server.hpp"

// clang-format off
#include <utility>  // before Asio, whose awaitable.hpp uses std::exchange without including it
// clang-format on

#include <time.h>

#include <algorithm>
#include <atomic>
#include <boost/asio.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <chrono>
#include <kestrel/error.hpp>
#include <map>
#include <mutex>
#include <set>
#include <thread>

#include "send_queue.hpp"

namespace kestrel::foxglove {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;

namespace {

std::int64_t thread_cpu_ns(clockid_t clock) {
  timespec t{};
  if (clock_gettime(clock, &t) != 0) return -1;
  return static_cast<std::int64_t>(t.tv_sec) * 1'000'000'000 + t.tv_nsec;
}

Frame text_frame(const std::string& text) {
  Frame f;
  f.text = true;
  f.head.assign(text.begin(), text.end());
  return f;
}

// Whether a Sec-WebSocket-Protocol header ("a, b, c") offers the protocol.
bool offers(std::string_view header, std::string_view protocol) {
  while (!header.empty()) {
    const std::size_t comma = header.find(',');
    std::string_view item = header.substr(0, comma);
    while (!item.empty() && item.front() == ' ') item.remove_prefix(1);
    while (!item.empty() && item.back() == ' ') item.remove_suffix(1);
    if (item == protocol) return true;
    if (comma == std::string_view::npos) break;
    header.remove_prefix(comma + 1);
  }
  return false;
}

}  // namespace

struct Session;

struct LiveServer::Impl {
  LiveServerOptions options;
  asio::io_context io{1};
  tcp::acceptor acceptor{io};
  asio::steady_timer stop_deadline{io};
  std::thread thread;
  std::string session_id;

  mutable std::mutex mutex;  // channels and subscriber counts, shared with the graph's thread
  std::vector<Channel> channels;
  std::map<std::uint32_t, int> subscribers;  // channel id -> subscriptions over all clients
  std::uint32_t next_channel = 1;

  std::set<std::shared_ptr<Session>> sessions;  // the I/O thread's alone
  bool stopping = false;

  std::atomic<std::uint64_t> clients{0}, open_clients{0}, max_clients{0}, rejected{0}, messages_sent{0}, bytes_sent{0},
      dropped{0};
  clockid_t io_clock = -1;                  // the I/O thread's CPU clock, while it runs
  std::atomic<std::int64_t> io_cpu_ns{-1};  // its CPU time, once it has ended

  void accept();
  void opened(const std::shared_ptr<Session>& s);
  void closed(const std::shared_ptr<Session>& s);
  void count_subscription(std::uint32_t channel, int delta) {
    std::lock_guard lock(mutex);
    if ((subscribers[channel] += delta) <= 0) subscribers.erase(channel);
  }
  bool has_channel(std::uint32_t id) {
    std::lock_guard lock(mutex);
    return std::ranges::any_of(channels, [&](const Channel& c) { return c.id == id; });
  }
};

struct Session : std::enable_shared_from_this<Session> {
  Session(tcp::socket socket, LiveServer::Impl& server)
      : ws(std::move(socket)), server(server), queue(server.options.client_queue_bytes) {}

  websocket::stream<beast::tcp_stream> ws;
  LiveServer::Impl& server;
  SendQueue queue;
  beast::flat_buffer buffer;
  http::request<http::string_body> request;
  std::map<std::uint32_t, std::uint32_t> subscriptions;  // subscription id -> channel id
  bool open = false, closing = false;
  std::uint64_t dropped_reported = 0;

  void start() {
    beast::get_lowest_layer(ws).expires_after(std::chrono::seconds(30));  // the HTTP upgrade must come soon
    http::async_read(beast::get_lowest_layer(ws), buffer, request,
                     [self = shared_from_this()](beast::error_code ec, std::size_t) { self->on_request(ec); });
  }

  void on_request(beast::error_code ec) {
    if (ec) return server.closed(shared_from_this());
    const bool upgrade = websocket::is_upgrade(request);
    const auto offered = request[http::field::sec_websocket_protocol];
    if (!upgrade || !offers(std::string_view(offered.data(), offered.size()), kSubprotocol)) {
      ++server.rejected;
      return reject(upgrade ? "the client must offer the WebSocket subprotocol foxglove.websocket.v1\n"
                            : "a Foxglove WebSocket server (foxglove.websocket.v1): connect with Foxglove, "
                              "Lichtblick or a foxglove.websocket.v1 client\n");
    }
    beast::get_lowest_layer(ws).expires_never();  // the WebSocket's own timeouts from here on
    ws.set_option(websocket::stream_base::timeout::suggested(beast::role_type::server));
    const std::string name = server.options.name;
    ws.set_option(websocket::stream_base::decorator([name](websocket::response_type& response) {
      response.set(http::field::sec_websocket_protocol, std::string(kSubprotocol));
      response.set(http::field::server, name);
    }));
    ws.async_accept(request, [self = shared_from_this()](beast::error_code e) {
      if (e) return self->server.closed(self);
      self->open = true;
      self->server.opened(self);
      self->read();
    });
  }

  void reject(const std::string& why) {
    auto response = std::make_shared<http::response<http::string_body>>(http::status::bad_request, request.version());
    response->set(http::field::content_type, "text/plain");
    response->set(http::field::server, server.options.name);
    response->body() = why;
    response->prepare_payload();
    http::async_write(beast::get_lowest_layer(ws), *response,
                      [self = shared_from_this(), response](beast::error_code, std::size_t) {
                        beast::get_lowest_layer(self->ws).close();
                        self->server.closed(self);
                      });
  }

  void read() {
    buffer.clear();
    ws.async_read(buffer, [self = shared_from_this()](beast::error_code ec, std::size_t) {
      if (ec) return self->server.closed(self);
      if (self->ws.got_text())
        self->handle(beast::buffers_to_string(self->buffer.data()));
      else
        self->send_status(StatusLevel::error, "binary client messages (clientPublish, services) are not supported");
      self->read();
    });
  }

  void handle(const std::string& text) {
    try {
      const ClientRequest request = parse_client_text(text);
      if (const auto* s = std::get_if<Subscribe>(&request)) {
        for (const Subscription& sub : s->subscriptions) {
          if (subscriptions.contains(sub.id)) {
            send_status(StatusLevel::error, "subscription id " + std::to_string(sub.id) + " is already in use");
          } else if (!server.has_channel(sub.channel_id)) {
            send_status(StatusLevel::error, "no channel " + std::to_string(sub.channel_id));
          } else {
            subscriptions.emplace(sub.id, sub.channel_id);
            server.count_subscription(sub.channel_id, +1);
          }
        }
      } else if (const auto* u = std::get_if<Unsubscribe>(&request)) {
        for (const std::uint32_t id : u->subscription_ids) {
          const auto it = subscriptions.find(id);
          if (it == subscriptions.end()) continue;  // the protocol allows it: nothing to stop
          server.count_subscription(it->second, -1);
          subscriptions.erase(it);
        }
      } else {
        send_status(StatusLevel::warning,
                    "'" + std::get<Unsupported>(request).op + "' is not supported by this server");
      }
    } catch (const ProtocolError& e) {
      send_status(StatusLevel::error, std::string("not a foxglove.websocket.v1 request: ") + e.what());
    }
  }

  void send_status(StatusLevel level, const std::string& message) { send(text_frame(status(level, message))); }

  void send(Frame frame) {
    if (!open || closing) return;
    const std::uint64_t before = queue.dropped();
    queue.push(std::move(frame));
    server.dropped += queue.dropped() - before;
    write_next();
  }

  void write_next() {
    if (closing) return;  // no write may start after the close
    const Frame* frame = queue.start_next();
    if (!frame) return;
    ws.text(frame->text);
    const std::array<asio::const_buffer, 2> buffers{asio::buffer(frame->head),
                                                    frame->body ? asio::buffer(*frame->body) : asio::const_buffer()};
    ws.async_write(buffers, [self = shared_from_this(), size = frame->size()](beast::error_code ec, std::size_t) {
      self->queue.sent();
      if (ec) return;  // the read fails too and closes the session
      ++self->server.messages_sent;
      self->server.bytes_sent += size;
      self->write_next();
    });
  }

  void close() {
    if (closing) return;
    closing = true;
    if (!open) {
      beast::get_lowest_layer(ws).close();
      return;
    }
    ws.async_close(websocket::close_code::going_away, [self = shared_from_this()](beast::error_code) {});
  }
};

void LiveServer::Impl::accept() {
  acceptor.async_accept([this](beast::error_code ec, tcp::socket socket) {
    if (!acceptor.is_open()) return;
    if (!ec) {
      beast::error_code ignored;
      socket.set_option(tcp::no_delay(true), ignored);  // a viewer wants each message now, not batched
      auto session = std::make_shared<Session>(std::move(socket), *this);
      sessions.insert(session);
      session->start();
    }
    accept();
  });
}

void LiveServer::Impl::opened(const std::shared_ptr<Session>& s) {
  const std::uint64_t now = ++open_clients;
  ++clients;
  for (std::uint64_t seen = max_clients; now > seen && !max_clients.compare_exchange_weak(seen, now);) {
  }
  std::vector<Channel> known;
  {
    std::lock_guard lock(mutex);
    known = channels;
  }
  s->send(text_frame(server_info(options.name, session_id)));
  s->send(text_frame(advertise(known)));
}

void LiveServer::Impl::closed(const std::shared_ptr<Session>& s) {
  if (!sessions.erase(s)) return;
  if (s->open) --open_clients;
  for (const auto& [_, channel] : s->subscriptions) count_subscription(channel, -1);
  s->subscriptions.clear();
  if (stopping && sessions.empty()) stop_deadline.cancel();
}

LiveServer::LiveServer(const LiveServerOptions& options) : impl_(std::make_unique<Impl>()) {
  Impl& s = *impl_;
  s.options = options;
  s.session_id = std::to_string(std::chrono::system_clock::now().time_since_epoch().count());
  const std::string where = options.address + ":" + std::to_string(options.port);
  beast::error_code ec;
  const auto address = asio::ip::make_address(options.address, ec);
  if (ec) throw Error("live view: '" + options.address + "' is not an IP address");
  const tcp::endpoint endpoint(address, options.port);
  s.acceptor.open(endpoint.protocol(), ec);
  if (!ec) s.acceptor.set_option(asio::socket_base::reuse_address(true), ec);
  if (!ec) s.acceptor.bind(endpoint, ec);
  if (!ec) s.acceptor.listen(asio::socket_base::max_listen_connections, ec);
  if (ec) throw Error("live view: cannot listen on " + where + ": " + ec.message());
  s.accept();
  s.thread = std::thread([&s] {
    s.io.run();
    s.io_cpu_ns = thread_cpu_ns(CLOCK_THREAD_CPUTIME_ID);
  });
  pthread_setname_np(s.thread.native_handle(), "kestrel-live");  // as top and perf show it
  if (pthread_getcpuclockid(s.thread.native_handle(), &s.io_clock) != 0) s.io_clock = -1;
}

LiveServer::~LiveServer() { stop(); }

std::uint16_t LiveServer::port() const {
  beast::error_code ec;
  const auto endpoint = impl_->acceptor.local_endpoint(ec);
  return ec ? impl_->options.port : endpoint.port();
}

std::uint32_t LiveServer::add_channel(Channel channel) {
  Impl& s = *impl_;
  {
    std::lock_guard lock(s.mutex);
    channel.id = s.next_channel++;
    s.channels.push_back(channel);
  }
  asio::post(s.io, [&s, channel] {
    const std::string text = advertise(std::span<const Channel>(&channel, 1));
    for (const auto& session : s.sessions) session->send(text_frame(text));
  });
  return channel.id;
}

bool LiveServer::subscribed(std::uint32_t channel_id) const {
  std::lock_guard lock(impl_->mutex);
  return impl_->subscribers.contains(channel_id);
}

void LiveServer::publish(std::uint32_t channel_id, std::uint64_t time_ns,
                         std::shared_ptr<const std::vector<std::uint8_t>> payload) {
  Impl& s = *impl_;
  asio::post(s.io, [&s, channel_id, time_ns, payload = std::move(payload)] {
    for (const auto& session : s.sessions)
      for (const auto& [subscription, channel] : session->subscriptions) {
        if (channel != channel_id) continue;
        const auto header = message_data_header(subscription, time_ns);
        session->send(Frame{false, true, {header.begin(), header.end()}, payload});
      }
  });
}

void LiveServer::publish_time(std::uint64_t time_ns) {
  Impl& s = *impl_;
  asio::post(s.io, [&s, time_ns] {
    const auto message = time_message(time_ns);
    for (const auto& session : s.sessions) session->send(Frame{false, true, {message.begin(), message.end()}, nullptr});
  });
}

void LiveServer::stop() {
  Impl& s = *impl_;
  if (!s.thread.joinable()) return;
  asio::post(s.io, [&s] {
    s.stopping = true;
    beast::error_code ignored;
    s.acceptor.close(ignored);
    if (s.sessions.empty()) return;
    // Clients get a second to answer the close; then the I/O thread ends regardless.
    s.stop_deadline.expires_after(std::chrono::seconds(1));
    s.stop_deadline.async_wait([&s](beast::error_code ec) {
      if (!ec) s.io.stop();
    });
    for (const auto& session : std::vector(s.sessions.begin(), s.sessions.end())) session->close();
  });
  s.thread.join();
}

LiveServerStats LiveServer::stats() const {
  const Impl& s = *impl_;
  std::int64_t cpu = s.io_cpu_ns;
  if (cpu < 0 && s.thread.joinable() && s.io_clock != -1) cpu = thread_cpu_ns(s.io_clock);
  return {s.clients,
          s.max_clients,
          s.rejected,
          s.messages_sent,
          s.bytes_sent,
          s.dropped,
          std::max<std::int64_t>(cpu, 0) * 1e-9};
}

}  // namespace kestrel::foxglove
