// The Foxglove WebSocket protocol's messages (plugins/foxglove_bridge/protocol.hpp) against the
// spec's byte layouts and JSON fields, and the per-client send queue's dropping rule.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "protocol.hpp"
#include "send_queue.hpp"

namespace kf = kestrel::foxglove;

TEST(FoxgloveProtocol, ServerInfoDeclaresTheTimeCapability) {
  const auto j = nlohmann::json::parse(kf::server_info("kestrel 0.1.0", "42"));
  EXPECT_EQ(j["op"], "serverInfo");
  EXPECT_EQ(j["name"], "kestrel 0.1.0");
  EXPECT_EQ(j["capabilities"], nlohmann::json::array({"time"}));
  EXPECT_EQ(j["sessionId"], "42");
}

TEST(FoxgloveProtocol, AdvertiseCarriesTheRos2SchemaAsText) {
  const kf::Channel c{7, "/camera/frame/left", "cdr", "sensor_msgs/msg/Image", "uint32 height\n", "ros2msg"};
  const auto j = nlohmann::json::parse(kf::advertise(std::span<const kf::Channel>(&c, 1)));
  EXPECT_EQ(j["op"], "advertise");
  ASSERT_EQ(j["channels"].size(), 1u);
  const auto& ch = j["channels"][0];
  EXPECT_EQ(ch["id"], 7);
  EXPECT_EQ(ch["topic"], "/camera/frame/left");
  EXPECT_EQ(ch["encoding"], "cdr");
  EXPECT_EQ(ch["schemaName"], "sensor_msgs/msg/Image");
  EXPECT_EQ(ch["schema"], "uint32 height\n");
  EXPECT_EQ(ch["schemaEncoding"], "ros2msg");
  const std::uint32_t ids[] = {3, 4};
  EXPECT_EQ(nlohmann::json::parse(kf::unadvertise(ids)),
            nlohmann::json::parse(R"({"op":"unadvertise","channelIds":[3,4]})"));
}

TEST(FoxgloveProtocol, BinaryFramesAreLittleEndianWithTheirOpcodes) {
  const auto h = kf::message_data_header(0x01020304u, 0x1112131415161718ull);
  const std::array<std::uint8_t, 13> want{0x01, 0x04, 0x03, 0x02, 0x01, 0x18, 0x17, 0x16, 0x15, 0x14, 0x13, 0x12, 0x11};
  EXPECT_EQ(h, want);
  const auto t = kf::time_message(1'000'000'000ull);  // 0x3B9ACA00
  const std::array<std::uint8_t, 9> want_time{0x02, 0x00, 0xCA, 0x9A, 0x3B, 0, 0, 0, 0};
  EXPECT_EQ(t, want_time);
}

TEST(FoxgloveProtocol, ParsesSubscribeAndUnsubscribe) {
  const auto s =
      kf::parse_client_text(R"({"op":"subscribe","subscriptions":[{"id":0,"channelId":3},{"id":1,"channelId":5}]})");
  const auto& sub = std::get<kf::Subscribe>(s);
  ASSERT_EQ(sub.subscriptions.size(), 2u);
  EXPECT_EQ(sub.subscriptions[1].id, 1u);
  EXPECT_EQ(sub.subscriptions[1].channel_id, 5u);
  const auto u = kf::parse_client_text(R"({"op":"unsubscribe","subscriptionIds":[0,4294967295]})");
  EXPECT_EQ(std::get<kf::Unsubscribe>(u).subscription_ids, (std::vector<std::uint32_t>{0, 4294967295u}));
  EXPECT_EQ(std::get<kf::Unsupported>(kf::parse_client_text(R"({"op":"getParameters","parameterNames":[]})")).op,
            "getParameters");
}

TEST(FoxgloveProtocol, MalformedRequestsAreProtocolErrorsThatSayWhy) {
  const auto error_of = [](std::string_view text) {
    try {
      kf::parse_client_text(text);
    } catch (const kf::ProtocolError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error_of("{"), "not JSON");
  EXPECT_EQ(error_of("[1]"), "not a JSON object");
  EXPECT_EQ(error_of(R"({"op":3})"), "no string \"op\"");
  EXPECT_EQ(error_of(R"({"op":"subscribe"})"), "subscribe needs an array \"subscriptions\"");
  EXPECT_EQ(error_of(R"({"op":"subscribe","subscriptions":[{"id":1}]})"), "a subscription has no \"channelId\"");
  EXPECT_EQ(error_of(R"({"op":"subscribe","subscriptions":[{"id":-1,"channelId":2}]})"),
            "a subscription: \"id\" must be an integer from 0 to 4294967295");
  EXPECT_EQ(error_of(R"({"op":"unsubscribe","subscriptionIds":[4294967296]})"),
            "unsubscribe: subscription ids must be integers from 0 to 4294967295");
}

namespace {
kf::Frame data(std::size_t bytes) { return kf::Frame{false, true, std::vector<std::uint8_t>(bytes, 0xAB), nullptr}; }
kf::Frame control(std::size_t bytes) { return kf::Frame{true, false, std::vector<std::uint8_t>(bytes, '{'), nullptr}; }
}  // namespace

TEST(SendQueue, AFullQueueDropsItsOldestDataFirst) {
  kf::SendQueue q(100);
  q.push(data(40));
  q.push(data(40));
  q.push(data(40));  // 120 > 100: the first goes
  EXPECT_EQ(q.dropped(), 1u);
  EXPECT_EQ(q.size(), 2u);
  EXPECT_EQ(q.bytes(), 80u);
}

TEST(SendQueue, ControlMessagesAreNeverDropped) {
  kf::SendQueue q(100);
  q.push(control(60));
  q.push(data(30));
  q.push(data(30));  // 120: the oldest data goes, the advertise stays
  EXPECT_EQ(q.dropped(), 1u);
  const kf::Frame* first = q.start_next();
  ASSERT_NE(first, nullptr);
  EXPECT_TRUE(first->text);
  q.push(control(200));  // queued even over the bound, after the remaining data made room
  EXPECT_EQ(q.dropped(), 2u);
  EXPECT_EQ(q.size(), 1u);
}

TEST(SendQueue, TheFrameBeingSentStaysUntilSentAndOneIsSentAtATime) {
  kf::SendQueue q(100);
  q.push(data(50));
  const kf::Frame* sending = q.start_next();
  ASSERT_NE(sending, nullptr);
  EXPECT_EQ(q.start_next(), nullptr);  // one WebSocket write at a time
  q.push(data(60));
  q.push(data(60));  // drops the queued 60, never the one in flight
  EXPECT_EQ(sending->size(), 50u);
  EXPECT_EQ(q.dropped(), 1u);
  q.sent();
  ASSERT_NE(q.start_next(), nullptr);
  EXPECT_EQ(q.bytes(), 0u);
}

TEST(SendQueue, DataLargerThanTheWholeQueueIsDroppedItself) {
  kf::SendQueue q(100);
  q.push(data(10));
  q.push(data(101));
  EXPECT_EQ(q.dropped(), 1u);
  EXPECT_EQ(q.size(), 1u);
}
