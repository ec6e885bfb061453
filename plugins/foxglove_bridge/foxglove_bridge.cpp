// The `foxglove_bridge` node: serves the outputs it taps to Foxglove, Lichtblick or any
// foxglove.websocket.v1 client, live (docs/recording.md). The channels, schemas and encoding are
// the recording's: ROS 2 messages in CDR on /NODE/PORT. A message is encoded only when a client
// subscribes to one of its channels, and the graph never waits for a client.
#include <fmt/format.h>

#include <kestrel/plugin.hpp>
#include <kestrel/ros2/definitions.hpp>
#include <kestrel/version.hpp>
#include <map>
#include <optional>
#include <set>

#include "kestrel/ros2_messages/message_mapping.hpp"
#include "live_server.hpp"

namespace kestrel::foxglove {

namespace {
// This machine only: 127.0.0.0/8, ::1, localhost.
bool loopback(const std::string& address) {
  return address.rfind("127.", 0) == 0 || address == "::1" || address == "localhost";
}
}  // namespace

struct BridgeConfig {
  std::int64_t port = 8765;
  std::string address = "127.0.0.1";
  std::string topics;
  std::int64_t client_queue_kib = 16384;
};

class FoxgloveBridgeNode final : public Node {
 public:
  static constexpr Input<AnyMessage> kIn{"in"};

  static NodeSpec spec() {
    using C = BridgeConfig;
    ConfigSpec<C> c;
    c.param("port", &C::port).range(0, 65535).describe("TCP port of the WebSocket server (0: any free port, logged)");
    c.param("address", &C::address)
        .describe(
            "address it listens on: 127.0.0.1 for this machine only (reach it from elsewhere through an SSH "
            "tunnel), 0.0.0.0 for every interface (anyone on the network can watch: a warning says so)");
    c.param("topics", &C::topics)
        .describe(
            "what is served: topic patterns /NODE/PORT separated by commas or spaces, '!PATTERN' to leave some out; "
            "empty: every connected output");
    c.param("client_queue_kib", &C::client_queue_kib)
        .with_unit("KiB")
        .range(64, 1 << 22)
        .describe("data waiting for one client; when a slow client fills it, its oldest messages are dropped");
    return NodeSpec("foxglove_bridge", "Serves the outputs it taps over the Foxglove WebSocket protocol")
        .details(
            "foxglove.websocket.v1 on Boost.Beast, with the time capability carrying the graph's clock. Channels "
            "are the recording's (docs/recording.md): /NODE/PORT, cdr encoding, ros2msg schemas, plus the derived "
            "markers and /tf. Each client has a bounded queue that drops its oldest data; the graph never waits.")
        .tap(kIn, "the outputs its topics select (or that a graph connects to it)", TapOptions{"topics", {}})
        .config(std::move(c));
  }

  explicit FoxgloveBridgeNode(NodeInit& init)
      : cfg_(init.config<BridgeConfig>()),
        server_(LiveServerOptions{cfg_.address, static_cast<std::uint16_t>(cfg_.port),
                                  static_cast<std::size_t>(cfg_.client_queue_kib) * 1024,
                                  std::string("kestrel ") + KESTREL_VERSION_STRING}) {
    // Scripts and tests wait for this line; with port 0 it is the only way to learn the port.
    init.log().info("live view: foxglove.websocket.v1 on ws://{}:{}", cfg_.address, server_.port());
    if (!loopback(cfg_.address))
      init.log().warn(
          "the live view listens on {}, open to the network without authentication: anyone who reaches port {} "
          "watches the camera and the tracks (listen on 127.0.0.1 and use an SSH tunnel, docs/recording.md)",
          cfg_.address, server_.port());
  }

  void process(Context& ctx) override {
    const Envelope& e = ctx.envelope(kIn.name);
    const auto at = static_cast<std::uint64_t>(std::max<std::int64_t>(0, e.published_at.count()));
    if (!last_time_ || at > *last_time_) {
      server_.publish_time(at);
      last_time_ = at;
    }
    const std::string topic = topic_of(e);
    const std::vector<std::uint32_t>* ids = channels_of(ctx.log(), e, topic);
    if (!ids || std::ranges::none_of(*ids, [&](std::uint32_t id) { return server_.subscribed(id); })) return;
    ros2::Encoded encoded = ros2::encode(e.type, e.payload.get(), topic);
    for (ros2::Ros2Message& m : encoded.messages) {
      const std::uint32_t id = ids->at(m.channel);
      if (!server_.subscribed(id)) continue;
      server_.publish(id, at, std::make_shared<const std::vector<std::uint8_t>>(std::move(m.cdr)));
      ++published_;
    }
  }

  void finish(Context& ctx) override {
    server_.stop();
    const LiveServerStats s = server_.stats();
    const std::string id = ctx.id();
    ctx.set_report_section(
        id, ReportSection()
                .quantity("port", server_.port())
                .quantity("channels", channel_ids_.size())
                .quantity("clients", s.clients)
                .quantity("max_clients", s.max_clients)
                .metric("rejected", s.rejected, "clients", Better::lower)
                .quantity("encoded", published_, "messages")
                .quantity("messages_sent", s.messages_sent, "messages")
                .quantity("bytes_sent", s.bytes_sent, "B")
                .metric("dropped", s.dropped, "messages", Better::lower)
                .metric("unserved", unserved_, "messages", Better::lower)
                .metric("io_cpu_s", s.io_cpu_s, "s", Better::lower)
                .markdown(fmt::format("Served {} channels on port {} to {} client(s) (at most {} at once): {} "
                                      "messages sent, {} dropped from slow clients' queues.\n",
                                      channel_ids_.size(), server_.port(), s.clients, s.max_clients, s.messages_sent,
                                      s.dropped)));
  }

 private:
  // The channel ids of an output's ROS 2 channels, advertised the first time the output
  // publishes; nullptr for a type with no ROS 2 mapping (counted, and warned about once).
  const std::vector<std::uint32_t>* channels_of(Logger& log, const Envelope& e, const std::string& topic) {
    if (auto it = by_output_.find(topic); it != by_output_.end()) return &it->second;
    if (!ros2::can_encode(e.type)) {
      if (unserved_types_.insert(std::string(e.type)).second)
        log.warn("{} messages (from {}.{}) have no ROS 2 mapping: they are not served", e.type, e.source_node,
                 e.source_port);
      ++unserved_;
      return nullptr;
    }
    std::vector<std::uint32_t> ids;
    for (const ros2::ChannelSpec& spec : ros2::channels_for(e.type, topic)) {
      // Outputs share a derived channel such as /tf: one channel per topic and type.
      const std::string key = spec.topic + '\n' + spec.schema;
      auto known = channel_ids_.find(key);
      if (known == channel_ids_.end())
        known = channel_ids_
                    .emplace(key, server_.add_channel(Channel{0, spec.topic, "cdr", spec.schema,
                                                              ros2::schema_text(spec.schema), "ros2msg"}))
                    .first;
      ids.push_back(known->second);
    }
    return &by_output_.emplace(topic, std::move(ids)).first->second;
  }

  BridgeConfig cfg_;
  LiveServer server_;
  std::map<std::string, std::vector<std::uint32_t>> by_output_;  // output topic -> its channels' ids
  std::map<std::string, std::uint32_t> channel_ids_;             // topic + schema -> channel id
  std::set<std::string> unserved_types_;
  std::uint64_t unserved_ = 0, published_ = 0;
  std::optional<std::uint64_t> last_time_;  // of the last Time frame sent
};
KESTREL_REGISTER_NODE(FoxgloveBridgeNode)

}  // namespace kestrel::foxglove
