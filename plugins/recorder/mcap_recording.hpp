#pragma once
// A run written as an MCAP file of ROS 2 messages: each tapped message is mapped
// (kestrel/ros2/message_mapping.hpp) and written on the channels of its output's topic, which are
// opened the first time they are needed. Messages of a type with no mapping are counted, never
// silently lost. Deterministic: the same messages in the same order give the same bytes.
#include <filesystem>
#include <kestrel/mcap/writer.hpp>
#include <kestrel/message.hpp>
#include <kestrel/report_section.hpp>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "kestrel/ros2_messages/message_mapping.hpp"

namespace kestrel::recorder {

struct RecordingOptions {
  std::string compression = "zstd";  ///< "zstd", "lz4" or "none"
  std::uint64_t chunk_size = 1 << 20;
};

class McapRecording {
 public:
  McapRecording(const std::filesystem::path& file, const RecordingOptions& options);

  /// Maps and writes one message. Throws kestrel::Error when a message cannot be encoded or the
  /// file cannot be written.
  void record(const Envelope& envelope);
  void write_metadata(const std::string& name, const mcap::KeyValues& values);
  /// Writes the summary and closes the file.
  void finish();

  /// Adds what was recorded to a section: "messages", "bytes", "channels", "by_topic":
  /// {TOPIC: count}, "unrecorded": {TYPE: count}.
  void report(ReportSection& section) const;
  std::uint64_t messages() const { return messages_; }
  std::size_t channels() const { return channels_.size(); }
  std::uint64_t unrecorded() const;

 private:
  std::uint16_t channel(const ros2::ChannelSpec& spec, const ros2::ChannelMetadata& metadata);

  mcap::Writer writer_;
  std::map<std::string, std::uint16_t> channels_;                // topic + schema + metadata -> channel id
  std::map<std::string, std::vector<ros2::ChannelSpec>> specs_;  // output topic -> its channels
  std::map<std::string, std::uint64_t> by_topic_;
  std::map<std::string, std::uint64_t> unrecorded_;
  std::uint64_t messages_ = 0, bytes_ = 0;
};

}  // namespace kestrel::recorder
