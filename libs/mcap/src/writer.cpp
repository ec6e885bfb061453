#include "kestrel/mcap/writer.hpp"

#include <algorithm>
#include <fstream>

#include "byte_io.hpp"
#include "compression.hpp"
#include "crc32.hpp"
#include "record_codec.hpp"

namespace kestrel::mcap {

struct Writer::State {
  WriterOptions options;
  std::unique_ptr<std::ofstream> file;
  std::ostream* out = nullptr;
  std::string name;  // for errors
  std::uint64_t position = 0;
  std::uint32_t data_crc = 0;  // over everything before Data End, magic and Header included
  bool finished = false;

  std::vector<Schema> schemas;    // id = index + 1
  std::vector<Channel> channels;  // id = index
  std::vector<bool> schema_written, channel_written;
  std::vector<std::uint32_t> sequences;

  // The chunk being filled.
  Bytes chunk_records;
  std::map<std::uint16_t, std::vector<std::pair<Timestamp, std::uint64_t>>> chunk_index;
  Timestamp chunk_start = 0, chunk_end = 0;
  bool chunk_has_messages = false;

  Statistics statistics;
  std::vector<ChunkIndex> chunk_indexes;
  std::vector<AttachmentIndex> attachment_indexes;
  std::vector<MetadataIndex> metadata_indexes;

  void emit(std::span<const std::uint8_t> bytes, bool data_section = true) {
    out->write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    if (!*out) throw Error("cannot write the MCAP file " + name);
    if (data_section) data_crc = crc32(data_crc, bytes);
    position += bytes.size();
  }

  void start() {
    if (!is_supported_compression(options.compression))
      throw Error("unknown MCAP chunk compression '" + options.compression + "' (known: none, zstd, lz4)");
    if (options.chunk_size == 0) throw Error("MCAP chunk_size must be positive");
    Bytes bytes(std::begin(kMagic), std::end(kMagic));
    ByteWriter w(bytes);
    write_record(w, Header{options.profile, options.library});
    emit(bytes);
  }

  void flush_chunk() {
    if (chunk_records.empty()) return;
    Chunk chunk;
    chunk.message_start_time = chunk_has_messages ? chunk_start : 0;
    chunk.message_end_time = chunk_has_messages ? chunk_end : 0;
    chunk.uncompressed_size = chunk_records.size();
    chunk.uncompressed_crc = crc32(0, chunk_records);
    chunk.compression = options.compression;
    chunk.records = compress(options.compression, chunk_records, options.compression_level);

    ChunkIndex index;
    index.message_start_time = chunk.message_start_time;
    index.message_end_time = chunk.message_end_time;
    index.compression = chunk.compression;
    index.compressed_size = chunk.records.size();
    index.uncompressed_size = chunk.uncompressed_size;
    index.chunk_start_offset = position;

    Bytes bytes;
    ByteWriter w(bytes);
    write_record(w, chunk);
    index.chunk_length = bytes.size();
    for (const auto& [channel, entries] : chunk_index) {
      index.message_index_offsets[channel] = position + bytes.size();
      write_record(w, MessageIndex{channel, entries});
    }
    index.message_index_length = bytes.size() - index.chunk_length;
    emit(bytes);
    out->flush();

    chunk_indexes.push_back(std::move(index));
    ++statistics.chunk_count;
    chunk_records.clear();
    chunk_index.clear();
    chunk_has_messages = false;
  }

  void finish() {
    if (finished) return;
    finished = true;
    flush_chunk();
    {
      Bytes bytes;
      ByteWriter w(bytes);
      write_record(w, DataEnd{data_crc});
      emit(bytes, false);
    }

    // The summary, grouped by opcode, and where each group starts.
    const std::uint64_t summary_start = position;
    Bytes summary;
    ByteWriter w(summary);
    std::vector<SummaryOffset> groups;
    const auto group = [&](Opcode opcode, auto&& write_all) {
      const std::size_t begin = summary.size();
      write_all();
      if (summary.size() > begin)
        groups.push_back({static_cast<std::uint8_t>(opcode), summary_start + begin, summary.size() - begin});
    };
    group(Opcode::schema, [&] {
      for (const Schema& s : schemas) write_record(w, s);
    });
    group(Opcode::channel, [&] {
      for (const Channel& c : channels) write_record(w, c);
    });
    group(Opcode::statistics, [&] { write_record(w, statistics); });
    group(Opcode::metadata_index, [&] {
      for (const MetadataIndex& m : metadata_indexes) write_record(w, m);
    });
    group(Opcode::attachment_index, [&] {
      for (const AttachmentIndex& a : attachment_indexes) write_record(w, a);
    });
    group(Opcode::chunk_index, [&] {
      for (const ChunkIndex& c : chunk_indexes) write_record(w, c);
    });
    const std::uint64_t summary_offset_start = summary_start + summary.size();
    for (const SummaryOffset& g : groups) write_record(w, g);

    // The summary CRC runs from the summary's start through the footer's summary_offset_start.
    Footer footer{summary_start, summary_offset_start, 0};
    Bytes footer_bytes;
    ByteWriter f(footer_bytes);
    write_record(f, footer);
    const std::size_t crc_covers = footer_bytes.size() - 4;
    footer.summary_crc = crc32(crc32(0, summary), std::span(footer_bytes).first(crc_covers));
    footer_bytes.clear();
    write_record(f, footer);
    f.raw(std::span<const std::uint8_t>(kMagic));

    emit(summary, false);
    emit(footer_bytes, false);
    out->flush();
    if (!*out) throw Error("cannot write the MCAP file " + name);
    if (file) {
      file->close();
      if (!*file) throw Error("cannot close the MCAP file " + name);
    }
  }
};

Writer::Writer(const std::filesystem::path& path, WriterOptions options) : state_(std::make_unique<State>()) {
  state_->options = std::move(options);
  state_->name = path.string();
  state_->file = std::make_unique<std::ofstream>(path, std::ios::binary | std::ios::trunc);
  if (!*state_->file) throw Error("cannot create the MCAP file " + path.string());
  state_->out = state_->file.get();
  state_->start();
}

Writer::Writer(std::ostream& out, WriterOptions options) : state_(std::make_unique<State>()) {
  state_->options = std::move(options);
  state_->name = "(stream)";
  state_->out = &out;
  state_->start();
}

Writer::~Writer() {
  try {
    finish();
  } catch (...) {  // NOLINT(bugprone-empty-catch): a destructor must not throw; finish() reports
  }
}

std::uint16_t Writer::add_schema(const std::string& name, const std::string& encoding,
                                 std::span<const std::uint8_t> data) {
  State& s = *state_;
  for (const Schema& known : s.schemas)
    if (known.name == name && known.encoding == encoding && std::ranges::equal(known.data, data)) return known.id;
  if (s.schemas.size() >= 0xFFFF) throw Error("an MCAP file holds at most 65535 schemas");
  s.schemas.push_back({static_cast<std::uint16_t>(s.schemas.size() + 1), name, encoding, {data.begin(), data.end()}});
  s.schema_written.push_back(false);
  s.statistics.schema_count = static_cast<std::uint16_t>(s.schemas.size());
  return s.schemas.back().id;
}

std::uint16_t Writer::add_channel(std::uint16_t schema_id, const std::string& topic,
                                  const std::string& message_encoding, const KeyValues& metadata) {
  State& s = *state_;
  if (schema_id > s.schemas.size()) throw Error("MCAP channel " + topic + ": no schema " + std::to_string(schema_id));
  if (s.channels.size() >= 0xFFFF) throw Error("an MCAP file holds at most 65535 channels");
  s.channels.push_back({static_cast<std::uint16_t>(s.channels.size()), schema_id, topic, message_encoding, metadata});
  s.channel_written.push_back(false);
  s.sequences.push_back(0);
  s.statistics.channel_count = static_cast<std::uint32_t>(s.channels.size());
  return s.channels.back().id;
}

void Writer::write_message(std::uint16_t channel_id, Timestamp log_time, Timestamp publish_time,
                           std::span<const std::uint8_t> data, std::optional<std::uint32_t> sequence) {
  State& s = *state_;
  if (s.finished) throw Error("MCAP writer: a message after finish()");
  if (channel_id >= s.channels.size()) throw Error("MCAP writer: no channel " + std::to_string(channel_id));
  ByteWriter w(s.chunk_records);
  // A chunk carries the schema and channel of its messages the first time they appear, so that a
  // file read from its start (or cut short) can decode every complete chunk.
  const Channel& channel = s.channels[channel_id];
  if (channel.schema_id != 0 && !s.schema_written[channel.schema_id - 1u]) {
    write_record(w, s.schemas[channel.schema_id - 1u]);
    s.schema_written[channel.schema_id - 1u] = true;
  }
  if (!s.channel_written[channel_id]) {
    write_record(w, channel);
    s.channel_written[channel_id] = true;
  }
  s.chunk_index[channel_id].emplace_back(log_time, s.chunk_records.size());
  const std::uint32_t counted = s.sequences[channel_id]++;
  Message message{channel_id, sequence.value_or(counted), log_time, publish_time, {}};
  const auto at = w.begin_record(Opcode::message);
  w.u16(message.channel_id);
  w.u32(message.sequence);
  w.u64(message.log_time);
  w.u64(message.publish_time);
  w.raw(data);
  w.end_record(at);

  s.chunk_start = s.chunk_has_messages ? std::min(s.chunk_start, log_time) : log_time;
  s.chunk_end = s.chunk_has_messages ? std::max(s.chunk_end, log_time) : log_time;
  s.chunk_has_messages = true;
  Statistics& st = s.statistics;
  st.message_start_time = st.message_count == 0 ? log_time : std::min(st.message_start_time, log_time);
  st.message_end_time = st.message_count == 0 ? log_time : std::max(st.message_end_time, log_time);
  ++st.message_count;
  ++st.channel_message_counts[channel_id];
  if (s.chunk_records.size() >= s.options.chunk_size) s.flush_chunk();
}

void Writer::write_metadata(const Metadata& metadata) {
  State& s = *state_;
  if (s.finished) throw Error("MCAP writer: metadata after finish()");
  Bytes bytes;
  ByteWriter w(bytes);
  write_record(w, metadata);
  s.metadata_indexes.push_back({s.position, bytes.size(), metadata.name});
  ++s.statistics.metadata_count;
  s.emit(bytes);
}

void Writer::write_attachment(const Attachment& attachment) {
  State& s = *state_;
  if (s.finished) throw Error("MCAP writer: an attachment after finish()");
  Bytes bytes;
  ByteWriter w(bytes);
  write_record(w, attachment, true);
  s.attachment_indexes.push_back({s.position, bytes.size(), attachment.log_time, attachment.create_time,
                                  attachment.data.size(), attachment.name, attachment.media_type});
  ++s.statistics.attachment_count;
  s.emit(bytes);
}

void Writer::finish() { state_->finish(); }

const Statistics& Writer::statistics() const { return state_->statistics; }
const WriterOptions& Writer::options() const { return state_->options; }

}  // namespace kestrel::mcap
