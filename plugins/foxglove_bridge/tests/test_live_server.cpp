// The live view's WebSocket server (plugins/foxglove_bridge/live_server.hpp) on a loopback
// socket, driven by a Boost.Beast client: the handshake and its subprotocol, serverInfo and
// advertise on connect, subscribe and unsubscribe, Message Data and Time frames, and a client
// that never reads, which must cost the publisher nothing and lose only its own oldest data.
#include <gtest/gtest.h>

// clang-format off
#include <utility>  // before Asio, whose awaitable.hpp uses std::exchange without including it
// clang-format on

#include <boost/asio.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <chrono>
#include <kestrel/error.hpp>
#include <nlohmann/json.hpp>
#include <thread>

#include "live_server.hpp"

namespace kf = kestrel::foxglove;
namespace asio = boost::asio;
namespace beast = boost::beast;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;

namespace {

kf::LiveServerOptions loopback(std::size_t queue_bytes = 1 << 20) {
  kf::LiveServerOptions o;
  o.address = "127.0.0.1";
  o.port = 0;
  o.client_queue_bytes = queue_bytes;
  o.name = "kestrel test";
  return o;
}

// A blocking foxglove.websocket.v1 client.
class Client {
 public:
  explicit Client(std::uint16_t port, std::string subprotocol = std::string(kf::kSubprotocol)) {
    tcp::resolver resolver(io_);
    asio::connect(ws_.next_layer(), resolver.resolve("127.0.0.1", std::to_string(port)));
    ws_.set_option(websocket::stream_base::decorator(
        [subprotocol](websocket::request_type& r) { r.set(beast::http::field::sec_websocket_protocol, subprotocol); }));
    ws_.handshake(response_, "127.0.0.1", "/");
  }
  const websocket::response_type& response() const { return response_; }

  nlohmann::json read_json() {
    read();
    EXPECT_TRUE(ws_.got_text());
    return nlohmann::json::parse(beast::buffers_to_string(buffer_.data()));
  }
  // The next binary frame, skipping Time frames unless asked for them.
  std::vector<std::uint8_t> read_binary(bool keep_time = false) {
    for (;;) {
      read();
      if (ws_.got_text()) continue;
      const auto bytes = beast::buffers_to_string(buffer_.data());
      std::vector<std::uint8_t> v(bytes.begin(), bytes.end());
      if (!keep_time && !v.empty() && v[0] == 0x02) continue;
      return v;
    }
  }
  void send(const nlohmann::json& j) {
    ws_.text(true);
    ws_.write(asio::buffer(j.dump()));
  }
  websocket::stream<tcp::socket>& stream() { return ws_; }

 private:
  void read() {
    buffer_.clear();
    ws_.read(buffer_);
  }
  asio::io_context io_;
  websocket::stream<tcp::socket> ws_{io_};
  websocket::response_type response_;
  beast::flat_buffer buffer_;
};

std::uint64_t le(const std::vector<std::uint8_t>& v, std::size_t at, std::size_t n) {
  std::uint64_t x = 0;
  for (std::size_t i = 0; i < n; ++i) x |= static_cast<std::uint64_t>(v.at(at + i)) << (8 * i);
  return x;
}

kf::Channel channel(const std::string& topic) {
  return kf::Channel{0, topic, "cdr", "std_msgs/msg/String", "string data\n", "ros2msg"};
}

std::shared_ptr<const std::vector<std::uint8_t>> payload(std::size_t n, std::uint8_t value) {
  return std::make_shared<const std::vector<std::uint8_t>>(n, value);
}

template <class Predicate>
bool eventually(Predicate p) {
  for (int i = 0; i < 500; ++i) {
    if (p()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return p();
}

}  // namespace

TEST(LiveServer, AClientGetsServerInfoThenTheChannelsAdvertised) {
  kf::LiveServer server(loopback());
  const std::uint32_t id = server.add_channel(channel("/camera/frame/left"));
  Client client(server.port());
  EXPECT_EQ(std::string(client.response()[beast::http::field::sec_websocket_protocol]), std::string(kf::kSubprotocol));
  const auto info = client.read_json();
  EXPECT_EQ(info["op"], "serverInfo");
  EXPECT_EQ(info["capabilities"], nlohmann::json::array({"time"}));
  const auto adv = client.read_json();
  ASSERT_EQ(adv["op"], "advertise");
  ASSERT_EQ(adv["channels"].size(), 1u);
  EXPECT_EQ(adv["channels"][0]["id"], id);
  EXPECT_EQ(adv["channels"][0]["topic"], "/camera/frame/left");
  // A channel added later is advertised to the clients already there.
  server.add_channel(channel("/tf"));
  EXPECT_EQ(client.read_json()["channels"][0]["topic"], "/tf");
}

TEST(LiveServer, SubscribersGetMessageDataWithTheirSubscriptionIdAndTime) {
  kf::LiveServer server(loopback());
  const std::uint32_t id = server.add_channel(channel("/clusters/detections"));
  Client client(server.port());
  client.read_json();
  client.read_json();
  EXPECT_FALSE(server.subscribed(id));
  client.send({{"op", "subscribe"}, {"subscriptions", {{{"id", 9}, {"channelId", id}}}}});
  ASSERT_TRUE(eventually([&] { return server.subscribed(id); }));
  server.publish_time(1'500'000'000);
  server.publish(id, 1'500'000'000, payload(5, 0x7F));
  const auto time = client.read_binary(/*keep_time=*/true);
  ASSERT_EQ(time.size(), 9u);
  EXPECT_EQ(time[0], 0x02);
  EXPECT_EQ(le(time, 1, 8), 1'500'000'000u);
  const auto data = client.read_binary();
  ASSERT_EQ(data.size(), 13u + 5u);
  EXPECT_EQ(data[0], 0x01);
  EXPECT_EQ(le(data, 1, 4), 9u);
  EXPECT_EQ(le(data, 5, 8), 1'500'000'000u);
  EXPECT_EQ(data[13], 0x7F);
  client.send({{"op", "unsubscribe"}, {"subscriptionIds", {9}}});
  EXPECT_TRUE(eventually([&] { return !server.subscribed(id); }));
}

TEST(LiveServer, BadRequestsGetAnErrorStatusAndTheConnectionStays) {
  kf::LiveServer server(loopback());
  const std::uint32_t id = server.add_channel(channel("/a/b"));
  Client client(server.port());
  client.read_json();
  client.read_json();
  client.send({{"op", "subscribe"}, {"subscriptions", {{{"id", 1}, {"channelId", 999}}}}});
  auto s = client.read_json();
  EXPECT_EQ(s["op"], "status");
  EXPECT_EQ(s["level"], 2);
  EXPECT_EQ(s["message"], "no channel 999");
  client.stream().text(true);
  client.stream().write(asio::buffer(std::string("{not json")));
  s = client.read_json();
  EXPECT_EQ(s["message"], "not a foxglove.websocket.v1 request: not JSON");
  client.send({{"op", "subscribe"}, {"subscriptions", {{{"id", 1}, {"channelId", id}}}}});
  client.send({{"op", "subscribe"}, {"subscriptions", {{{"id", 1}, {"channelId", id}}}}});
  EXPECT_EQ(client.read_json()["message"], "subscription id 1 is already in use");
}

TEST(LiveServer, AClientWithoutTheSubprotocolIsRefused) {
  kf::LiveServer server(loopback());
  EXPECT_THROW(Client(server.port(), "some.other.protocol"), beast::system_error);
  EXPECT_TRUE(eventually([&] { return server.stats().rejected == 1; }));
  EXPECT_EQ(server.stats().clients, 0u);
}

TEST(LiveServer, ASlowClientLosesItsOldestDataAndNeitherThePublisherNorOtherClientsWait) {
  kf::LiveServer server(loopback(/*queue_bytes=*/1 << 20));
  const std::uint32_t id = server.add_channel(channel("/camera/frame/left"));
  Client slow(server.port());  // subscribes, then never reads again
  slow.read_json();
  slow.read_json();
  slow.send({{"op", "subscribe"}, {"subscriptions", {{{"id", 1}, {"channelId", id}}}}});
  Client fast(server.port());
  fast.read_json();
  fast.read_json();
  fast.send({{"op", "subscribe"}, {"subscriptions", {{{"id", 2}, {"channelId", id}}}}});
  // Both subscribed once the fast client gets a probe and the slow one has dropped nothing yet.
  ASSERT_TRUE(eventually([&] { return server.stats().max_clients == 2 && server.subscribed(id); }));
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  // 32 MiB, one message at a time as the fast client reads them: far more than the slow client's
  // queue and socket buffers hold. The fast client gets every one while the slow one stalls.
  constexpr int kMessages = 512;
  constexpr std::size_t kBytes = 64 << 10;
  for (int i = 0; i < kMessages; ++i) {
    server.publish(id, static_cast<std::uint64_t>(i), payload(kBytes, static_cast<std::uint8_t>(i)));
    const auto m = fast.read_binary();
    ASSERT_EQ(m.size(), kf::kMessageDataHeader + kBytes);
    ASSERT_EQ(le(m, 1, 4), 2u);
    ASSERT_EQ(le(m, 5, 8), static_cast<std::uint64_t>(i));
    ASSERT_EQ(m[13], static_cast<std::uint8_t>(i));
  }
  EXPECT_GT(server.stats().dropped, 0u);  // all the slow client's: the fast one got every message
}

TEST(LiveServer, ListeningOnAPortInUseNamesTheAddress) {
  kf::LiveServer first(loopback());
  kf::LiveServerOptions same = loopback();
  same.port = first.port();
  try {
    kf::LiveServer second(same);
    FAIL() << "a second server listened on the same port";
  } catch (const kestrel::Error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot listen on 127.0.0.1:" + std::to_string(first.port())),
              std::string::npos)
        << e.what();
  }
}

// Listening on 127.0.0.1 (the default) is this machine's loopback only: a client coming through
// another local address, 127.0.0.2, is refused; listening on every interface lets it in.
TEST(LiveServer, TheDefaultAddressServesOnlyThisMachinesLoopback) {
  const auto reaches = [](std::uint16_t port) {
    asio::io_context io;
    tcp::socket socket(io);
    boost::system::error_code ec;
    socket.connect({asio::ip::make_address("127.0.0.2"), port}, ec);
    return !ec;
  };
  kf::LiveServer local(loopback());
  EXPECT_FALSE(reaches(local.port()));
  kf::LiveServerOptions open = loopback();
  open.address = "0.0.0.0";
  kf::LiveServer everywhere(open);
  EXPECT_TRUE(reaches(everywhere.port()));
  EXPECT_EQ(kf::LiveServerOptions{}.address, "127.0.0.1");
}

TEST(LiveServer, StopsWithClientsConnected) {
  kf::LiveServer server(loopback());
  Client a(server.port());
  Client b(server.port());
  a.read_json();
  ASSERT_TRUE(eventually([&] { return server.stats().max_clients == 2; }));
  const auto started = std::chrono::steady_clock::now();
  server.stop();
  EXPECT_LT(std::chrono::steady_clock::now() - started, std::chrono::seconds(5));
}
