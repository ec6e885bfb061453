#include "protocol.hpp"

#include <nlohmann/json.hpp>

namespace kestrel::foxglove {

namespace {

template <std::size_t N>
void put_le(std::uint8_t* out, std::uint64_t value) {
  for (std::size_t i = 0; i < N; ++i) out[i] = static_cast<std::uint8_t>(value >> (8 * i));
}

std::uint32_t id_field(const nlohmann::json& j, const char* key, std::string_view where) {
  const auto it = j.find(key);
  if (it == j.end()) throw ProtocolError(std::string(where) + " has no \"" + key + "\"");
  if (!it->is_number_unsigned() || it->get<std::uint64_t>() > 0xffffffffu)
    throw ProtocolError(std::string(where) + ": \"" + key + "\" must be an integer from 0 to 4294967295");
  return static_cast<std::uint32_t>(it->get<std::uint64_t>());
}

const nlohmann::json& array_field(const nlohmann::json& j, const char* key, std::string_view op) {
  const auto it = j.find(key);
  if (it == j.end() || !it->is_array()) throw ProtocolError(std::string(op) + " needs an array \"" + key + "\"");
  return *it;
}

}  // namespace

std::string server_info(std::string_view name, std::string_view session_id) {
  return nlohmann::json{{"op", "serverInfo"},
                        {"name", name},
                        {"capabilities", {"time"}},
                        {"metadata", nlohmann::json::object()},
                        {"sessionId", session_id}}
      .dump();
}

std::string advertise(std::span<const Channel> channels) {
  nlohmann::json list = nlohmann::json::array();
  for (const Channel& c : channels)
    list.push_back({{"id", c.id},
                    {"topic", c.topic},
                    {"encoding", c.encoding},
                    {"schemaName", c.schema_name},
                    {"schema", c.schema},
                    {"schemaEncoding", c.schema_encoding}});
  return nlohmann::json{{"op", "advertise"}, {"channels", std::move(list)}}.dump();
}

std::string unadvertise(std::span<const std::uint32_t> channel_ids) {
  return nlohmann::json{{"op", "unadvertise"}, {"channelIds", channel_ids}}.dump();
}

std::string status(StatusLevel level, std::string_view message) {
  return nlohmann::json{{"op", "status"}, {"level", static_cast<int>(level)}, {"message", message}}.dump();
}

std::array<std::uint8_t, kMessageDataHeader> message_data_header(std::uint32_t subscription_id,
                                                                 std::uint64_t receive_time_ns) {
  std::array<std::uint8_t, kMessageDataHeader> h{};
  h[0] = 0x01;
  put_le<4>(&h[1], subscription_id);
  put_le<8>(&h[5], receive_time_ns);
  return h;
}

std::array<std::uint8_t, 9> time_message(std::uint64_t time_ns) {
  std::array<std::uint8_t, 9> m{};
  m[0] = 0x02;
  put_le<8>(&m[1], time_ns);
  return m;
}

ClientRequest parse_client_text(std::string_view text) {
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded()) throw ProtocolError("not JSON");
  if (!j.is_object()) throw ProtocolError("not a JSON object");
  const auto op_it = j.find("op");
  if (op_it == j.end() || !op_it->is_string()) throw ProtocolError("no string \"op\"");
  const std::string op = op_it->get<std::string>();
  if (op == "subscribe") {
    Subscribe s;
    for (const auto& entry : array_field(j, "subscriptions", op)) {
      if (!entry.is_object()) throw ProtocolError("subscribe: each subscription must be an object");
      s.subscriptions.push_back(
          {id_field(entry, "id", "a subscription"), id_field(entry, "channelId", "a subscription")});
    }
    return s;
  }
  if (op == "unsubscribe") {
    Unsubscribe u;
    for (const auto& id : array_field(j, "subscriptionIds", op)) {
      if (!id.is_number_unsigned() || id.get<std::uint64_t>() > 0xffffffffu)
        throw ProtocolError("unsubscribe: subscription ids must be integers from 0 to 4294967295");
      u.subscription_ids.push_back(static_cast<std::uint32_t>(id.get<std::uint64_t>()));
    }
    return u;
  }
  return Unsupported{op};
}

}  // namespace kestrel::foxglove
