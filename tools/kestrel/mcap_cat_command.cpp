// kestrel mcap cat FILE [--topic T]... [--limit N]: one JSON line per message,
// {"log_time": NS, "topic": T, "message": {...}}, in log-time order. CDR messages with a ros2msg
// schema are decoded from the schema alone, so any ROS 2 bag reads; JSON messages pass through.
#include <cstdio>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>

#include "command_errors.hpp"
#include "commands.hpp"
#include "kestrel/mcap/reader.hpp"
#include "kestrel/ros2/cdr_json.hpp"

namespace kestrel::cli {

namespace {

// How one channel's messages become JSON.
class ChannelDecoder {
 public:
  ChannelDecoder(const mcap::Channel& channel, const mcap::Schema* schema) : encoding_(channel.message_encoding) {
    if (encoding_ == "cdr") {
      if (!schema || schema->encoding != "ros2msg")
        throw Error("channel " + channel.topic + ": cdr messages need a ros2msg schema, this one has " +
                    (schema ? "'" + schema->encoding + "'" : std::string("none")));
      ros2_ =
          std::make_unique<ros2::MessageSchema>(schema->name, std::string(schema->data.begin(), schema->data.end()));
    } else if (encoding_ != "json") {
      throw Error("channel " + channel.topic + ": cannot decode message encoding '" + encoding_ +
                  "' (known: cdr with ros2msg, json)");
    }
  }

  nlohmann::ordered_json decode(const mcap::Message& m) const {
    if (ros2_) return ros2::cdr_to_json(*ros2_, m.data);
    auto parsed = nlohmann::ordered_json::parse(m.data.begin(), m.data.end(), nullptr, false);
    if (parsed.is_discarded()) throw Error("a json message is not JSON");
    return parsed;
  }

 private:
  std::string encoding_;
  std::unique_ptr<ros2::MessageSchema> ros2_;
};

}  // namespace

int mcap_cat_command(const McapCatArgs& args) {
  return run_command_body("mcap cat", [&] {
    mcap::Reader reader(args.file);
    for (const std::string& topic : args.topics) {
      bool known = false;
      for (const auto& [id, c] : reader.summary().channels) known = known || c.topic == topic;
      if (!known) throw Error("no channel '" + topic + "' in " + args.file + " (kestrel mcap info lists them)");
    }
    mcap::MessageFilter filter;
    filter.topics = args.topics;
    std::map<std::uint16_t, ChannelDecoder> decoders;
    std::uint64_t printed = 0;
    struct Done {};
    try {
      reader.read_messages(filter, [&](const mcap::MessageView& m) {
        if (args.limit && printed >= *args.limit) throw Done{};
        auto it = decoders.find(m.channel.id);
        if (it == decoders.end()) it = decoders.emplace(m.channel.id, ChannelDecoder(m.channel, m.schema)).first;
        nlohmann::ordered_json line;
        line["log_time"] = m.message.log_time;
        line["topic"] = m.channel.topic;
        try {
          line["message"] = it->second.decode(m.message);
        } catch (const Error& e) {
          throw Error(m.channel.topic + ", message at log time " + std::to_string(m.message.log_time) + ": " +
                      e.what());
        }
        std::printf("%s\n", line.dump().c_str());
        ++printed;
      });
    } catch (const Done&) {
    }
    std::fflush(stdout);
    return kOk;
  });
}

}  // namespace kestrel::cli
