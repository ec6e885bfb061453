#pragma once
// The Foxglove WebSocket protocol, foxglove.websocket.v1 (docs/recording.md): the server's
// messages as text or bytes, and the client's requests parsed from what arrives on a socket.
// No I/O here, so that the parser can be fuzzed and the messages checked byte by byte.
#include <array>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace kestrel::foxglove {

inline constexpr std::string_view kSubprotocol = "foxglove.websocket.v1";

/// A channel as Advertise describes it.
struct Channel {
  std::uint32_t id = 0;
  std::string topic;
  std::string encoding;         ///< "cdr"
  std::string schema_name;      ///< "sensor_msgs/msg/Image"
  std::string schema;           ///< the schema's text
  std::string schema_encoding;  ///< "ros2msg"
};

enum class StatusLevel { info = 0, warning = 1, error = 2 };

// Server to client, as JSON text.
std::string server_info(std::string_view name, std::string_view session_id);
std::string advertise(std::span<const Channel> channels);
std::string unadvertise(std::span<const std::uint32_t> channel_ids);
std::string status(StatusLevel level, std::string_view message);

// Server to client, binary. A Message Data frame is this header followed by the payload.
inline constexpr std::size_t kMessageDataHeader = 1 + 4 + 8;
std::array<std::uint8_t, kMessageDataHeader> message_data_header(std::uint32_t subscription_id,
                                                                 std::uint64_t receive_time_ns);
std::array<std::uint8_t, 9> time_message(std::uint64_t time_ns);

// Client to server.
struct Subscription {
  std::uint32_t id = 0;
  std::uint32_t channel_id = 0;
};
struct Subscribe {
  std::vector<Subscription> subscriptions;
};
struct Unsubscribe {
  std::vector<std::uint32_t> subscription_ids;
};
/// A well-formed request for a capability this server does not declare (parameters, services...).
struct Unsupported {
  std::string op;
};
using ClientRequest = std::variant<Subscribe, Unsubscribe, Unsupported>;

/// A client's message that does not follow the protocol; what() says why.
class ProtocolError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Parses a text message from a client. Throws ProtocolError on anything but a JSON object with
/// a string `op` and, for subscribe and unsubscribe, their fields with ids in 0..2^32-1.
ClientRequest parse_client_text(std::string_view text);

}  // namespace kestrel::foxglove
