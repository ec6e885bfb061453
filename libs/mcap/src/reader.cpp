#include "kestrel/mcap/reader.hpp"

#include <algorithm>
#include <cstring>
#include <fstream>

#include "byte_io.hpp"
#include "compression.hpp"
#include "crc32.hpp"
#include "record_codec.hpp"

namespace kestrel::mcap {

namespace {

constexpr std::uint64_t kMagicSize = sizeof(kMagic);
constexpr std::uint64_t kRecordPrefix = 9;                   // opcode and uint64 length
constexpr std::uint64_t kFooterRecord = kRecordPrefix + 20;  // summary_start, summary_offset_start, crc

std::string at_byte(std::uint64_t offset) { return " at byte " + std::to_string(offset); }

// Bytes of the file, from disk or memory.
class Source {
 public:
  virtual ~Source() = default;
  virtual std::uint64_t size() const = 0;
  /// Throws Error when the bytes cannot be read; callers check the range first.
  virtual void read(std::uint64_t offset, std::span<std::uint8_t> out) = 0;
};

class FileSource final : public Source {
 public:
  explicit FileSource(const std::filesystem::path& path) : name_(path.string()), file_(path, std::ios::binary) {
    if (!file_) throw Error("cannot open the MCAP file " + name_);
    file_.seekg(0, std::ios::end);
    size_ = static_cast<std::uint64_t>(file_.tellg());
  }
  std::uint64_t size() const override { return size_; }
  void read(std::uint64_t offset, std::span<std::uint8_t> out) override {
    file_.clear();
    file_.seekg(static_cast<std::streamoff>(offset));
    file_.read(reinterpret_cast<char*>(out.data()), static_cast<std::streamsize>(out.size()));
    if (!file_) throw Error("cannot read " + std::to_string(out.size()) + " bytes" + at_byte(offset) + " of " + name_);
  }

 private:
  std::string name_;
  std::ifstream file_;
  std::uint64_t size_ = 0;
};

class MemorySource final : public Source {
 public:
  explicit MemorySource(Bytes bytes) : bytes_(std::move(bytes)) {}
  std::uint64_t size() const override { return bytes_.size(); }
  void read(std::uint64_t offset, std::span<std::uint8_t> out) override {
    std::memcpy(out.data(), bytes_.data() + offset, out.size());
  }

 private:
  Bytes bytes_;
};

struct RecordAt {
  std::uint8_t opcode = 0;
  std::uint64_t offset = 0;  // of the opcode
  std::uint64_t length = 0;  // of the content
  std::uint64_t end() const { return offset + kRecordPrefix + length; }
};

// Visits the records of a chunk's uncompressed bytes.
template <class Visit>
void for_each_inner_record(std::span<const std::uint8_t> records, std::uint64_t chunk_offset, Visit&& visit) {
  ByteReader in(records, "Chunk" + at_byte(chunk_offset));
  while (!in.done()) {
    const std::uint64_t inner_offset = in.position();
    const std::uint8_t opcode = in.u8();
    const std::uint64_t length = in.u64();
    ByteReader content(in.take(length, "a record in the chunk"), opcode_name(opcode) + " record at offset " +
                                                                     std::to_string(inner_offset) + " of the Chunk" +
                                                                     at_byte(chunk_offset));
    visit(opcode, content);
  }
}

bool wanted(const MessageFilter& f, const Channel& c, Timestamp t) {
  if (f.start && t < *f.start) return false;
  if (f.end && t >= *f.end) return false;
  return f.topics.empty() || std::ranges::find(f.topics, c.topic) != f.topics.end();
}

}  // namespace

struct Reader::State {
  ReaderOptions options;
  std::unique_ptr<Source> source;
  Summary summary;
  std::vector<std::string> problems;
  std::optional<Footer> footer;
  std::uint64_t footer_offset = 0;

  std::uint64_t size() const { return source->size(); }

  Bytes read_bytes(std::uint64_t offset, std::uint64_t n, const std::string& what) {
    if (offset > size() || n > size() - offset)
      throw FormatError(what + ": " + std::to_string(n) + " bytes" + at_byte(offset) +
                        " run past the end of the file (" + std::to_string(size()) + " bytes)");
    if (n > options.max_record_bytes)
      throw FormatError(what + at_byte(offset) + " is " + std::to_string(n) +
                        " bytes, more than the reader's limit of " + std::to_string(options.max_record_bytes));
    Bytes out(static_cast<std::size_t>(n));
    if (n > 0) source->read(offset, out);  // an empty vector's data() may be null, which memcpy must not get
    return out;
  }

  // The record starting at `offset`, or nullopt when the file ends inside it.
  std::optional<RecordAt> record_at(std::uint64_t offset) {
    if (offset > size() || size() - offset < kRecordPrefix) return std::nullopt;
    Bytes prefix = read_bytes(offset, kRecordPrefix, "a record");
    ByteReader in(prefix, "record" + at_byte(offset));
    RecordAt r;
    r.opcode = in.u8();
    r.length = in.u64();
    r.offset = offset;
    if (r.length > size() - offset - kRecordPrefix) return std::nullopt;
    return r;
  }

  Bytes content(const RecordAt& r) {
    return read_bytes(r.offset + kRecordPrefix, r.length, opcode_name(r.opcode) + " record");
  }

  std::string where(const RecordAt& r) const { return opcode_name(r.opcode) + " record" + at_byte(r.offset); }

  Bytes chunk_records(const Chunk& chunk, std::uint64_t offset) {
    if (chunk.uncompressed_size > options.max_record_bytes)
      throw FormatError("Chunk" + at_byte(offset) + " holds " + std::to_string(chunk.uncompressed_size) +
                        " bytes, more than the reader's limit of " + std::to_string(options.max_record_bytes));
    if (!is_supported_compression(chunk.compression))
      throw FormatError("Chunk" + at_byte(offset) + ": unknown compression '" + chunk.compression + "'");
    Bytes records = decompress(chunk.compression, chunk.records, chunk.uncompressed_size);
    if (chunk.uncompressed_crc != 0 && crc32(0, records) != chunk.uncompressed_crc)
      throw FormatError("Chunk" + at_byte(offset) + ": CRC mismatch");
    return records;
  }

  void open() {
    if (size() < kMagicSize) throw FormatError("not an MCAP file: " + std::to_string(size()) + " bytes");
    const Bytes magic = read_bytes(0, kMagicSize, "the magic");
    if (!std::equal(magic.begin(), magic.end(), std::begin(kMagic)))
      throw FormatError("not an MCAP file: the magic bytes are missing");
    const auto first = record_at(kMagicSize);
    if (!first) throw FormatError("the file ends inside its Header record");
    if (first->opcode != static_cast<std::uint8_t>(Opcode::header))
      throw FormatError("the first record is a " + where(*first) + ", not a Header");
    const Bytes header = content(*first);
    ByteReader in(header, where(*first));
    summary.header = parse_header(in);
    read_footer();
    if (!read_summary()) scan_for_summary();
  }

  void read_footer() {
    if (size() < 2 * kMagicSize + kFooterRecord) return;
    const std::uint64_t at = size() - kMagicSize - kFooterRecord;
    const Bytes tail = read_bytes(at, kFooterRecord + kMagicSize, "the footer");
    if (!std::equal(tail.end() - kMagicSize, tail.end(), std::begin(kMagic))) return;
    ByteReader in(tail, "Footer" + at_byte(at));
    if (in.u8() != static_cast<std::uint8_t>(Opcode::footer) || in.u64() != 20) return;
    footer = parse_footer(in);
    footer_offset = at;
  }

  // The summary section, if there is one and its CRC matches. False: scan instead.
  bool read_summary() {
    if (!footer) {
      problems.push_back("the file has no footer (cut short?): read by streaming from its start");
      return false;
    }
    if (footer->summary_start == 0) return false;
    const std::uint64_t start = footer->summary_start;
    if (start < kMagicSize || start > footer_offset) {
      problems.push_back("the footer's summary_start" + at_byte(start) + " is outside the file: not used");
      return false;
    }
    const Bytes section = read_bytes(start, footer_offset - start, "the summary section");
    if (footer->summary_crc != 0) {
      const Bytes footer_head = read_bytes(footer_offset, kRecordPrefix + 16, "the footer");
      if (crc32(crc32(0, section), footer_head) != footer->summary_crc) {
        problems.push_back("the summary's CRC does not match: read by streaming from the start");
        return false;
      }
    }
    const std::uint64_t summary_end = footer->summary_offset_start != 0 && footer->summary_offset_start >= start &&
                                              footer->summary_offset_start <= footer_offset
                                          ? footer->summary_offset_start
                                          : footer_offset;
    Summary s;
    s.header = summary.header;
    bool have_statistics = false;
    ByteReader in{std::span<const std::uint8_t>(section).first(static_cast<std::size_t>(summary_end - start)),
                  "the summary section"};
    while (!in.done()) {
      const std::uint64_t offset = start + in.position();
      const std::uint8_t opcode = in.u8();
      ByteReader record(in.take(in.u64(), "a summary record"), opcode_name(opcode) + " record" + at_byte(offset));
      switch (static_cast<Opcode>(opcode)) {
        case Opcode::schema: {
          Schema schema = parse_schema(record);
          if (schema.id != 0) s.schemas[schema.id] = std::move(schema);
          break;
        }
        case Opcode::channel: {
          Channel channel = parse_channel(record);
          s.channels[channel.id] = std::move(channel);
          break;
        }
        case Opcode::statistics:
          s.statistics = parse_statistics(record);
          have_statistics = true;
          break;
        case Opcode::chunk_index:
          s.chunk_indexes.push_back(parse_chunk_index(record));
          break;
        case Opcode::attachment_index:
          s.attachment_indexes.push_back(parse_attachment_index(record));
          break;
        case Opcode::metadata_index:
          s.metadata_indexes.push_back(parse_metadata_index(record));
          break;
        default:
          break;  // other records may appear; they do not change what is read
      }
    }
    if (!have_statistics || (s.chunk_indexes.empty() && s.statistics.message_count > 0)) {
      problems.push_back("the summary has no statistics or no chunk indexes: read by streaming from the start");
      return false;
    }
    for (const ChunkIndex& c : s.chunk_indexes)
      if (c.chunk_start_offset < kMagicSize || c.chunk_length > size() ||
          c.chunk_start_offset > size() - c.chunk_length)
        throw FormatError("a Chunk Index points" + at_byte(c.chunk_start_offset) + " outside the file");
    s.indexed = true;
    summary = std::move(s);
    return true;
  }

  // Streams through the data section from the start: each top-level record to `top`, each record
  // of each chunk to `inner`. Stops at Data End, at the footer, or where the file was cut short
  // (said in problems). Returns the offset where the data section ended.
  template <class Top, class Inner>
  std::uint64_t stream(Top&& top, Inner&& inner) {
    std::uint64_t offset = kMagicSize;
    const auto first = record_at(offset);
    offset = first->end();  // the Header, checked in open()
    while (offset < size()) {
      const auto r = record_at(offset);
      if (!r) {
        if (offset + kMagicSize == size()) break;  // the trailing magic of a file without footer
        problems.push_back("the file ends inside a record" + at_byte(offset) + " (" + std::to_string(size() - offset) +
                           " bytes left): every complete chunk before it was read");
        return offset;
      }
      const auto opcode = static_cast<Opcode>(r->opcode);
      if (opcode == Opcode::data_end || opcode == Opcode::footer) return offset;
      if (opcode == Opcode::chunk) {
        const Bytes bytes = content(*r);
        ByteReader in(bytes, where(*r));
        const Chunk chunk = parse_chunk(in);
        const Bytes records = chunk_records(chunk, r->offset);
        top(*r, &chunk, nullptr);
        for_each_inner_record(records, r->offset, inner);
      } else {
        const Bytes bytes = content(*r);
        ByteReader in(bytes, where(*r));
        top(*r, nullptr, &in);
        inner(r->opcode, in.position() == 0 ? in : in);
      }
      offset = r->end();
    }
    return offset;
  }

  void scan_for_summary() {
    Summary s;
    s.header = summary.header;
    Statistics& st = s.statistics;
    stream(
        [&](const RecordAt& r, const Chunk* chunk, ByteReader* in) {
          if (chunk) {
            ++st.chunk_count;
            s.chunk_indexes.push_back({chunk->message_start_time,
                                       chunk->message_end_time,
                                       r.offset,
                                       r.end() - r.offset,
                                       {},
                                       0,
                                       chunk->compression,
                                       chunk->records.size(),
                                       chunk->uncompressed_size});
          } else if (r.opcode == static_cast<std::uint8_t>(Opcode::attachment)) {
            const Attachment a = parse_attachment(*in);
            s.attachment_indexes.push_back(
                {r.offset, r.end() - r.offset, a.log_time, a.create_time, a.data.size(), a.name, a.media_type});
            ++st.attachment_count;
            *in = ByteReader({}, "");  // consumed
          } else if (r.opcode == static_cast<std::uint8_t>(Opcode::metadata)) {
            const Metadata m = parse_metadata(*in);
            s.metadata_indexes.push_back({r.offset, r.end() - r.offset, m.name});
            ++st.metadata_count;
            *in = ByteReader({}, "");
          }
        },
        [&](std::uint8_t opcode, ByteReader& in) {
          switch (static_cast<Opcode>(opcode)) {
            case Opcode::schema: {
              Schema schema = parse_schema(in);
              if (schema.id != 0) s.schemas[schema.id] = std::move(schema);
              break;
            }
            case Opcode::channel: {
              Channel channel = parse_channel(in);
              s.channels[channel.id] = std::move(channel);
              break;
            }
            case Opcode::message: {
              const std::uint16_t channel = in.u16();
              in.u32();
              const Timestamp t = in.u64();
              st.message_start_time = st.message_count == 0 ? t : std::min(st.message_start_time, t);
              st.message_end_time = st.message_count == 0 ? t : std::max(st.message_end_time, t);
              ++st.message_count;
              ++st.channel_message_counts[channel];
              break;
            }
            default:
              break;
          }
        });
    st.schema_count = static_cast<std::uint16_t>(s.schemas.size());
    st.channel_count = static_cast<std::uint32_t>(s.channels.size());
    summary = std::move(s);
  }
};

Reader::Reader(const std::filesystem::path& path, ReaderOptions options) : state_(std::make_unique<State>()) {
  state_->options = options;
  state_->source = std::make_unique<FileSource>(path);
  state_->open();
}

Reader::Reader(Bytes bytes, ReaderOptions options) : state_(std::make_unique<State>()) {
  state_->options = options;
  state_->source = std::make_unique<MemorySource>(std::move(bytes));
  state_->open();
}

Reader::~Reader() = default;

const Summary& Reader::summary() const { return state_->summary; }
const std::vector<std::string>& Reader::problems() const { return state_->problems; }

void Reader::read_messages(const MessageFilter& filter, const std::function<void(const MessageView&)>& on_message) {
  State& s = *state_;
  const auto schema_of = [&](const std::map<std::uint16_t, Schema>& schemas, const Channel& c) -> const Schema* {
    const auto it = schemas.find(c.schema_id);
    return it == schemas.end() ? nullptr : &it->second;
  };
  if (!s.summary.indexed) {
    std::map<std::uint16_t, Schema> schemas;
    std::map<std::uint16_t, Channel> channels;
    s.stream([](const RecordAt&, const Chunk*, ByteReader*) {},
             [&](std::uint8_t opcode, ByteReader& in) {
               switch (static_cast<Opcode>(opcode)) {
                 case Opcode::schema: {
                   Schema schema = parse_schema(in);
                   if (schema.id != 0) schemas[schema.id] = std::move(schema);
                   break;
                 }
                 case Opcode::channel: {
                   Channel channel = parse_channel(in);
                   channels[channel.id] = std::move(channel);
                   break;
                 }
                 case Opcode::message: {
                   const Message m = parse_message(in);
                   const auto c = channels.find(m.channel_id);
                   if (c == channels.end())
                     throw FormatError(in.what() + ": a message on channel " + std::to_string(m.channel_id) +
                                       ", which no Channel record before it defines");
                   if (wanted(filter, c->second, m.log_time)) on_message({c->second, schema_of(schemas, c->second), m});
                   break;
                 }
                 default:
                   break;
               }
             });
    return;
  }

  // Indexed: the chunks that overlap the range and hold a wanted channel, by start time; their
  // messages merged in log-time order (ties in the order read).
  std::vector<const ChunkIndex*> chunks;
  for (const ChunkIndex& c : s.summary.chunk_indexes) {
    if (filter.start && c.message_end_time < *filter.start) continue;
    if (filter.end && c.message_start_time >= *filter.end) continue;
    if (!filter.topics.empty() && !c.message_index_offsets.empty()) {
      const bool any = std::ranges::any_of(c.message_index_offsets, [&](const auto& entry) {
        const auto it = s.summary.channels.find(entry.first);
        return it != s.summary.channels.end() &&
               std::ranges::find(filter.topics, it->second.topic) != filter.topics.end();
      });
      if (!any) continue;
    }
    chunks.push_back(&c);
  }
  std::ranges::stable_sort(chunks, {}, [](const ChunkIndex* c) { return c->message_start_time; });
  std::multimap<std::pair<Timestamp, std::uint64_t>, Message> pending;
  std::uint64_t order = 0;
  const auto emit_before = [&](std::optional<Timestamp> limit) {
    while (!pending.empty() && (!limit || pending.begin()->first.first < *limit)) {
      const Message& m = pending.begin()->second;
      const Channel& c = s.summary.channels.at(m.channel_id);
      on_message({c, schema_of(s.summary.schemas, c), m});
      pending.erase(pending.begin());
    }
  };
  for (const ChunkIndex* index : chunks) {
    emit_before(index->message_start_time);
    const auto r = s.record_at(index->chunk_start_offset);
    if (!r || r->opcode != static_cast<std::uint8_t>(Opcode::chunk))
      throw FormatError("the Chunk Index for" + at_byte(index->chunk_start_offset) + " does not point at a Chunk");
    const Bytes bytes = s.content(*r);
    ByteReader in(bytes, s.where(*r));
    const Bytes records = s.chunk_records(parse_chunk(in), r->offset);
    for_each_inner_record(records, r->offset, [&](std::uint8_t opcode, ByteReader& record) {
      if (opcode != static_cast<std::uint8_t>(Opcode::message)) return;
      Message m = parse_message(record);
      const auto c = s.summary.channels.find(m.channel_id);
      if (c == s.summary.channels.end())
        throw FormatError(record.what() + ": a message on channel " + std::to_string(m.channel_id) +
                          ", which the summary does not list");
      if (wanted(filter, c->second, m.log_time)) pending.emplace(std::pair(m.log_time, order++), std::move(m));
    });
  }
  emit_before(std::nullopt);
}

std::vector<Metadata> Reader::metadata() {
  State& s = *state_;
  std::vector<Metadata> out;
  for (const MetadataIndex& index : s.summary.metadata_indexes) {
    const auto r = s.record_at(index.offset);
    if (!r || r->opcode != static_cast<std::uint8_t>(Opcode::metadata))
      throw FormatError("the Metadata Index '" + index.name + "' does not point at a Metadata record");
    const Bytes bytes = s.content(*r);
    ByteReader in(bytes, s.where(*r));
    out.push_back(parse_metadata(in));
  }
  return out;
}

std::vector<Attachment> Reader::attachments() {
  State& s = *state_;
  std::vector<Attachment> out;
  for (const AttachmentIndex& index : s.summary.attachment_indexes) {
    const auto r = s.record_at(index.offset);
    if (!r || r->opcode != static_cast<std::uint8_t>(Opcode::attachment))
      throw FormatError("the Attachment Index '" + index.name + "' does not point at an Attachment record");
    const Bytes bytes = s.content(*r);
    ByteReader in(bytes, s.where(*r));
    out.push_back(parse_attachment(in));
  }
  return out;
}

Verification Reader::verify() {
  State& s = *state_;
  Verification v;
  std::uint32_t crc = 0;
  std::uint64_t covered = 0;  // bytes of the file the running CRC has seen
  const auto extend_crc = [&](std::uint64_t to) {
    while (covered < to) {
      const std::uint64_t n = std::min<std::uint64_t>(to - covered, 1 << 20);
      crc = crc32(crc, s.read_bytes(covered, n, "the data section"));
      covered += n;
    }
  };
  const std::uint64_t data_end = s.stream(
      [&](const RecordAt& r, const Chunk* chunk, ByteReader* in) {
        if (chunk) {
          ++v.chunks;  // its CRC was checked when it was decompressed
          if (chunk->uncompressed_crc != 0) ++v.chunks_with_crc;
        } else if (r.opcode == static_cast<std::uint8_t>(Opcode::attachment)) {
          ++v.attachments;
          if (parse_attachment(*in).crc != 0) ++v.attachments_with_crc;
          *in = ByteReader({}, "");
        }
      },
      [](std::uint8_t, ByteReader&) {});
  const auto r = s.record_at(data_end);
  if (r && r->opcode == static_cast<std::uint8_t>(Opcode::data_end)) {
    const Bytes bytes = s.content(*r);
    ByteReader in(bytes, s.where(*r));
    const DataEnd end = parse_data_end(in);
    if (end.data_section_crc != 0) {
      extend_crc(data_end);
      if (crc != end.data_section_crc) throw FormatError("the data section's CRC does not match");
      v.data_section_crc_present = true;
    }
  }
  if (s.footer && s.footer->summary_crc != 0 && s.summary.indexed) v.summary_crc_present = true;
  return v;
}

}  // namespace kestrel::mcap
