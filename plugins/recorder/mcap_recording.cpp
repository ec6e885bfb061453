#include "mcap_recording.hpp"

#include <kestrel/error.hpp>
#include <kestrel/ros2/definitions.hpp>

namespace kestrel::recorder {

namespace {

mcap::WriterOptions writer_options(const RecordingOptions& o) {
  mcap::WriterOptions w;
  w.profile = "ros2";
  w.compression = o.compression == "none" ? "" : o.compression;
  w.chunk_size = o.chunk_size;
  return w;
}

// As --report does, the file's folder is made when it is missing.
const std::filesystem::path& with_folder(const std::filesystem::path& file) {
  std::error_code ec;
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path(), ec);
  return file;
}
}  // namespace

McapRecording::McapRecording(const std::filesystem::path& file, const RecordingOptions& options)
    : writer_(with_folder(file), writer_options(options)) {}

std::uint16_t McapRecording::channel(const ros2::ChannelSpec& spec, const ros2::ChannelMetadata& metadata) {
  std::string key = spec.topic + '\n' + spec.schema;
  for (const auto& [k, v] : metadata) key += '\n' + k + '=' + v;
  if (auto it = channels_.find(key); it != channels_.end()) return it->second;
  const std::string& text = ros2::schema_text(spec.schema);
  const std::uint16_t schema =
      writer_.add_schema(spec.schema, "ros2msg", {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()});
  mcap::KeyValues values(metadata.begin(), metadata.end());
  const std::uint16_t id = writer_.add_channel(schema, spec.topic, "cdr", values);
  channels_.emplace(key, id);
  return id;
}

void McapRecording::record(const Envelope& e) {
  const std::string type(e.type);
  if (!ros2::can_encode(type)) {
    ++unrecorded_[type];
    return;
  }
  const std::string topic = topic_of(e);
  auto known = specs_.find(topic);
  if (known == specs_.end()) known = specs_.emplace(topic, ros2::channels_for(type, topic)).first;
  const auto& specs = known->second;
  const ros2::Encoded encoded = ros2::encode(type, e.payload.get(), topic);
  const auto at = static_cast<mcap::Timestamp>(std::max<std::int64_t>(0, e.published_at.count()));
  for (const auto& m : encoded.messages) {
    const ros2::ChannelSpec& spec = specs.at(m.channel);
    const std::uint16_t id = channel(spec, spec.derived ? ros2::ChannelMetadata{} : encoded.metadata);
    writer_.write_message(id, at, at, m.cdr, m.sequence);
    ++by_topic_[spec.topic];
    ++messages_;
    bytes_ += m.cdr.size();
  }
}

void McapRecording::write_metadata(const std::string& name, const mcap::KeyValues& values) {
  writer_.write_metadata(mcap::Metadata{name, values});
}

void McapRecording::finish() { writer_.finish(); }

void McapRecording::report(ReportSection& section) const {
  section.quantity("messages", messages_)
      .quantity("bytes", bytes_, "B")
      .quantity("channels", channels_.size())
      .quantity("by_topic", by_topic_)
      .metric("unrecorded", unrecorded_, "messages", Better::lower);
}

std::uint64_t McapRecording::unrecorded() const {
  std::uint64_t n = 0;
  for (const auto& [_, count] : unrecorded_) n += count;
  return n;
}

}  // namespace kestrel::recorder
