// The kestrel side of the MCAP interop test (check_mcap_core.sh):
//   mcap_tool write DIR   writes none.mcap, zstd.mcap and lz4.mcap with kestrel's writer and
//                         prints, as JSON, the messages each holds, in the order written;
//   mcap_tool dump FILE   reads FILE with kestrel's reader and prints its messages (in the
//                         reader's order), metadata and attachments as JSON.
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

#include "kestrel/mcap/reader.hpp"
#include "kestrel/mcap/writer.hpp"

using namespace kestrel::mcap;

namespace {

std::string hex(const Bytes& data) {
  static const char digits[] = "0123456789abcdef";
  std::string out;
  for (const std::uint8_t b : data) {
    out += digits[b >> 4];
    out += digits[b & 15];
  }
  return out;
}

Bytes text(const std::string& s) { return {s.begin(), s.end()}; }

nlohmann::json write(const std::string& dir) {
  nlohmann::json files;
  for (const std::string compression : {"", "zstd", "lz4"}) {
    const std::string name = compression.empty() ? "none" : compression;
    WriterOptions options;
    options.profile = "ros2";
    options.compression = compression;
    options.chunk_size = 400;
    Writer writer(dir + "/" + name + ".mcap", options);
    const auto schema = writer.add_schema("std_msgs/msg/String", "ros2msg", text("string data\n"));
    const std::uint16_t channels[] = {writer.add_channel(schema, "/text", "cdr", {{"node", "talker"}}),
                                      writer.add_channel(0, "/raw", "json")};
    writer.write_metadata({"run", {{"seed", "7"}, {"graph", "nodes: []"}}});
    nlohmann::json messages = nlohmann::json::array();
    std::uint32_t sequence[2] = {0, 0};
    for (int i = 0; i < 60; ++i) {
      const int c = i % 3 == 0 ? 1 : 0;
      const Timestamp log_time = 1'000'000ull * static_cast<Timestamp>((i * 7) % 60);
      std::string payload = "message " + std::to_string(i) + " ";
      for (int k = 0; k < i % 5; ++k) payload += payload;
      const Bytes data = text(payload);
      writer.write_message(channels[c], log_time, log_time + 5, data);
      messages.push_back({{"channel_id", channels[c]},
                          {"sequence", sequence[c]++},
                          {"log_time", std::to_string(log_time)},
                          {"publish_time", std::to_string(log_time + 5)},
                          {"data", hex(data)}});
      if (i == 30) writer.write_attachment({3, 2, "notes.txt", "text/plain", text("hello"), 0});
    }
    writer.finish();
    files[name] = {{"messages", messages}};
  }
  return files;
}

nlohmann::json dump(const std::string& file) {
  Reader reader(file);
  nlohmann::json messages = nlohmann::json::array();
  reader.read_messages({}, [&](const MessageView& m) {
    messages.push_back({{"topic", m.channel.topic},
                        {"channel_id", m.channel.id},
                        {"sequence", m.message.sequence},
                        {"log_time", std::to_string(m.message.log_time)},
                        {"publish_time", std::to_string(m.message.publish_time)},
                        {"data", hex(m.message.data)}});
  });
  nlohmann::json metadata = nlohmann::json::array(), attachments = nlohmann::json::array();
  for (const Metadata& m : reader.metadata()) metadata.push_back({{"name", m.name}, {"metadata", m.metadata}});
  for (const Attachment& a : reader.attachments())
    attachments.push_back({{"name", a.name}, {"media_type", a.media_type}, {"data", hex(a.data)}});
  reader.verify();
  return {{"indexed", reader.summary().indexed},
          {"messages", messages},
          {"metadata", metadata},
          {"attachments", attachments}};
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: mcap_tool write DIR | dump FILE\n");
    return 2;
  }
  try {
    const std::string mode = argv[1];
    const nlohmann::json out = mode == "write" ? write(argv[2]) : dump(argv[2]);
    std::printf("%s\n", out.dump().c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "mcap_tool: %s\n", e.what());
    return 1;
  }
  return 0;
}
