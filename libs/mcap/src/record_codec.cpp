#include "record_codec.hpp"

#include "crc32.hpp"

namespace kestrel::mcap {

namespace {

void write_map(ByteWriter& out, const KeyValues& map) {
  const auto at = out.begin_prefix();
  for (const auto& [key, value] : map) {
    out.string(key);
    out.string(value);
  }
  out.end_prefix(at);
}

KeyValues read_map(ByteReader& in, const char* field) {
  ByteReader group = in.group(field);
  KeyValues map;
  while (!group.done()) {
    std::string key = group.string("a key");
    map[std::move(key)] = group.string("a value");
  }
  return map;
}

template <class Value>
void write_id_map(ByteWriter& out, const std::map<std::uint16_t, Value>& map) {
  const auto at = out.begin_prefix();
  for (const auto& [key, value] : map) {
    out.u16(key);
    out.u64(value);
  }
  out.end_prefix(at);
}

std::map<std::uint16_t, std::uint64_t> read_id_map(ByteReader& in, const char* field) {
  ByteReader group = in.group(field);
  std::map<std::uint16_t, std::uint64_t> map;
  while (!group.done()) {
    const std::uint16_t key = group.u16();
    map[key] = group.u64();
  }
  return map;
}

}  // namespace

std::string opcode_name(std::uint8_t opcode) {
  static const char* const names[] = {
      "",         "Header",         "Footer",         "Schema",     "Channel",          "Message",
      "Chunk",    "Message Index",  "Chunk Index",    "Attachment", "Attachment Index", "Statistics",
      "Metadata", "Metadata Index", "Summary Offset", "Data End"};
  if (opcode >= 1 && opcode <= 0x0F) return names[opcode];
  static const char hex[] = "0123456789ABCDEF";
  return std::string("opcode 0x") + hex[opcode >> 4] + hex[opcode & 0xF];
}

void write_record(ByteWriter& out, const Header& r) {
  const auto at = out.begin_record(Opcode::header);
  out.string(r.profile);
  out.string(r.library);
  out.end_record(at);
}

void write_record(ByteWriter& out, const Footer& r) {
  const auto at = out.begin_record(Opcode::footer);
  out.u64(r.summary_start);
  out.u64(r.summary_offset_start);
  out.u32(r.summary_crc);
  out.end_record(at);
}

void write_record(ByteWriter& out, const Schema& r) {
  const auto at = out.begin_record(Opcode::schema);
  out.u16(r.id);
  out.string(r.name);
  out.string(r.encoding);
  out.bytes_u32(r.data);
  out.end_record(at);
}

void write_record(ByteWriter& out, const Channel& r) {
  const auto at = out.begin_record(Opcode::channel);
  out.u16(r.id);
  out.u16(r.schema_id);
  out.string(r.topic);
  out.string(r.message_encoding);
  write_map(out, r.metadata);
  out.end_record(at);
}

void write_record(ByteWriter& out, const Message& r) {
  const auto at = out.begin_record(Opcode::message);
  out.u16(r.channel_id);
  out.u32(r.sequence);
  out.u64(r.log_time);
  out.u64(r.publish_time);
  out.raw(r.data);
  out.end_record(at);
}

void write_record(ByteWriter& out, const Chunk& r) {
  const auto at = out.begin_record(Opcode::chunk);
  out.u64(r.message_start_time);
  out.u64(r.message_end_time);
  out.u64(r.uncompressed_size);
  out.u32(r.uncompressed_crc);
  out.string(r.compression);
  out.bytes_u64(r.records);
  out.end_record(at);
}

void write_record(ByteWriter& out, const MessageIndex& r) {
  const auto at = out.begin_record(Opcode::message_index);
  out.u16(r.channel_id);
  const auto array = out.begin_prefix();
  for (const auto& [time, offset] : r.records) {
    out.u64(time);
    out.u64(offset);
  }
  out.end_prefix(array);
  out.end_record(at);
}

void write_record(ByteWriter& out, const ChunkIndex& r) {
  const auto at = out.begin_record(Opcode::chunk_index);
  out.u64(r.message_start_time);
  out.u64(r.message_end_time);
  out.u64(r.chunk_start_offset);
  out.u64(r.chunk_length);
  write_id_map(out, r.message_index_offsets);
  out.u64(r.message_index_length);
  out.string(r.compression);
  out.u64(r.compressed_size);
  out.u64(r.uncompressed_size);
  out.end_record(at);
}

void write_record(ByteWriter& out, const Attachment& r, bool with_crc) {
  const auto at = out.begin_record(Opcode::attachment);
  Bytes fields;
  ByteWriter f(fields);
  f.u64(r.log_time);
  f.u64(r.create_time);
  f.string(r.name);
  f.string(r.media_type);
  f.bytes_u64(r.data);
  out.raw(fields);
  out.u32(with_crc ? crc32(0, fields) : 0);
  out.end_record(at);
}

void write_record(ByteWriter& out, const AttachmentIndex& r) {
  const auto at = out.begin_record(Opcode::attachment_index);
  out.u64(r.offset);
  out.u64(r.length);
  out.u64(r.log_time);
  out.u64(r.create_time);
  out.u64(r.data_size);
  out.string(r.name);
  out.string(r.media_type);
  out.end_record(at);
}

void write_record(ByteWriter& out, const Statistics& r) {
  const auto at = out.begin_record(Opcode::statistics);
  out.u64(r.message_count);
  out.u16(r.schema_count);
  out.u32(r.channel_count);
  out.u32(r.attachment_count);
  out.u32(r.metadata_count);
  out.u32(r.chunk_count);
  out.u64(r.message_start_time);
  out.u64(r.message_end_time);
  write_id_map(out, r.channel_message_counts);
  out.end_record(at);
}

void write_record(ByteWriter& out, const Metadata& r) {
  const auto at = out.begin_record(Opcode::metadata);
  out.string(r.name);
  write_map(out, r.metadata);
  out.end_record(at);
}

void write_record(ByteWriter& out, const MetadataIndex& r) {
  const auto at = out.begin_record(Opcode::metadata_index);
  out.u64(r.offset);
  out.u64(r.length);
  out.string(r.name);
  out.end_record(at);
}

void write_record(ByteWriter& out, const SummaryOffset& r) {
  const auto at = out.begin_record(Opcode::summary_offset);
  out.u8(r.group_opcode);
  out.u64(r.group_start);
  out.u64(r.group_length);
  out.end_record(at);
}

void write_record(ByteWriter& out, const DataEnd& r) {
  const auto at = out.begin_record(Opcode::data_end);
  out.u32(r.data_section_crc);
  out.end_record(at);
}

Header parse_header(ByteReader& in) {
  Header r;
  r.profile = in.string("profile");
  r.library = in.string("library");
  return r;
}

Footer parse_footer(ByteReader& in) {
  Footer r;
  r.summary_start = in.u64();
  r.summary_offset_start = in.u64();
  r.summary_crc = in.u32();
  return r;
}

Schema parse_schema(ByteReader& in) {
  Schema r;
  r.id = in.u16();
  r.name = in.string("name");
  r.encoding = in.string("encoding");
  r.data = in.bytes_u32("data");
  return r;
}

Channel parse_channel(ByteReader& in) {
  Channel r;
  r.id = in.u16();
  r.schema_id = in.u16();
  r.topic = in.string("topic");
  r.message_encoding = in.string("message_encoding");
  r.metadata = read_map(in, "metadata");
  return r;
}

Message parse_message(ByteReader& in) {
  Message r;
  r.channel_id = in.u16();
  r.sequence = in.u32();
  r.log_time = in.u64();
  r.publish_time = in.u64();
  const auto data = in.take(in.remaining(), "data");
  r.data.assign(data.begin(), data.end());
  return r;
}

Chunk parse_chunk(ByteReader& in) {
  Chunk r;
  r.message_start_time = in.u64();
  r.message_end_time = in.u64();
  r.uncompressed_size = in.u64();
  r.uncompressed_crc = in.u32();
  r.compression = in.string("compression");
  r.records = in.bytes_u64("records");
  return r;
}

MessageIndex parse_message_index(ByteReader& in) {
  MessageIndex r;
  r.channel_id = in.u16();
  ByteReader array = in.group("records");
  while (!array.done()) {
    const Timestamp time = array.u64();
    r.records.emplace_back(time, array.u64());
  }
  return r;
}

ChunkIndex parse_chunk_index(ByteReader& in) {
  ChunkIndex r;
  r.message_start_time = in.u64();
  r.message_end_time = in.u64();
  r.chunk_start_offset = in.u64();
  r.chunk_length = in.u64();
  r.message_index_offsets = read_id_map(in, "message_index_offsets");
  r.message_index_length = in.u64();
  r.compression = in.string("compression");
  r.compressed_size = in.u64();
  r.uncompressed_size = in.u64();
  return r;
}

Attachment parse_attachment(ByteReader& in) {
  Attachment r;
  r.log_time = in.u64();
  r.create_time = in.u64();
  r.name = in.string("name");
  r.media_type = in.string("media_type");
  r.data = in.bytes_u64("data");
  const std::uint32_t computed = crc32(0, in.consumed());
  r.crc = in.u32();
  if (r.crc != 0 && r.crc != computed) throw FormatError(in.what() + ": CRC mismatch in attachment '" + r.name + "'");
  return r;
}

AttachmentIndex parse_attachment_index(ByteReader& in) {
  AttachmentIndex r;
  r.offset = in.u64();
  r.length = in.u64();
  r.log_time = in.u64();
  r.create_time = in.u64();
  r.data_size = in.u64();
  r.name = in.string("name");
  r.media_type = in.string("media_type");
  return r;
}

Statistics parse_statistics(ByteReader& in) {
  Statistics r;
  r.message_count = in.u64();
  r.schema_count = in.u16();
  r.channel_count = in.u32();
  r.attachment_count = in.u32();
  r.metadata_count = in.u32();
  r.chunk_count = in.u32();
  r.message_start_time = in.u64();
  r.message_end_time = in.u64();
  r.channel_message_counts = read_id_map(in, "channel_message_counts");
  return r;
}

Metadata parse_metadata(ByteReader& in) {
  Metadata r;
  r.name = in.string("name");
  r.metadata = read_map(in, "metadata");
  return r;
}

MetadataIndex parse_metadata_index(ByteReader& in) {
  MetadataIndex r;
  r.offset = in.u64();
  r.length = in.u64();
  r.name = in.string("name");
  return r;
}

SummaryOffset parse_summary_offset(ByteReader& in) {
  SummaryOffset r;
  r.group_opcode = in.u8();
  r.group_start = in.u64();
  r.group_length = in.u64();
  return r;
}

DataEnd parse_data_end(ByteReader& in) { return DataEnd{in.u32()}; }

}  // namespace kestrel::mcap
