// The MCAP writer and reader: round trips, determinism, and files that are cut short or corrupt.
#include <gmock/gmock.h>
#include <zlib.h>

#include <sstream>

#include "kestrel/mcap/reader.hpp"
#include "kestrel/mcap/writer.hpp"

using namespace kestrel;
using namespace kestrel::mcap;

namespace {

Bytes bytes_of(const std::string& text) { return {text.begin(), text.end()}; }

struct Written {
  std::uint16_t channel;
  Timestamp log_time;
  Bytes data;
};

// A file with two schemas, three channels (one without a schema), 300 messages spread over many
// small chunks, metadata and an attachment. `log` receives what was written.
Bytes sample_file(const std::string& compression, std::vector<Written>* log = nullptr,
                  std::uint64_t chunk_size = 2000) {
  std::ostringstream out;
  WriterOptions options;
  options.profile = "ros2";
  options.compression = compression;
  options.chunk_size = chunk_size;
  Writer writer(out, options);
  const auto pose = writer.add_schema("geometry_msgs/msg/Pose", "ros2msg", bytes_of("geometry_msgs/Point position\n"));
  const auto image = writer.add_schema("sensor_msgs/msg/Image", "ros2msg", bytes_of("uint32 height\nuint32 width\n"));
  EXPECT_EQ(writer.add_schema("geometry_msgs/msg/Pose", "ros2msg", bytes_of("geometry_msgs/Point position\n")), pose);
  const std::uint16_t channels[] = {writer.add_channel(pose, "/truth/pose", "cdr", {{"node", "truth"}}),
                                    writer.add_channel(image, "/camera/frame/left", "cdr"),
                                    writer.add_channel(0, "/log", "json")};
  writer.write_metadata({"kestrel", {{"seed", "1"}, {"graph", "nodes: []"}}});
  for (int i = 0; i < 300; ++i) {
    const std::uint16_t channel = channels[i % 3];
    Bytes data(static_cast<std::size_t>(10 + (i * 37) % 200));
    for (std::size_t k = 0; k < data.size(); ++k) data[k] = static_cast<std::uint8_t>(i + k * k);
    const Timestamp t = 1'000'000ull * static_cast<Timestamp>(i);
    writer.write_message(channel, t, t, data);
    if (log) log->push_back({channel, t, data});
    if (i == 150) writer.write_attachment({t, 0, "calibration.yaml", "text/yaml", bytes_of("fx: 452\n"), 0});
  }
  writer.finish();
  return bytes_of(out.str());
}

std::vector<Written> read_all(Reader& reader, const MessageFilter& filter = {}) {
  std::vector<Written> out;
  reader.read_messages(filter, [&](const MessageView& m) {
    out.push_back({m.channel.id, m.message.log_time, m.message.data});
  });
  return out;
}

bool same(const std::vector<Written>& a, const std::vector<Written>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].channel != b[i].channel || a[i].log_time != b[i].log_time || a[i].data != b[i].data) return false;
  return true;
}

}  // namespace

class McapRoundTrip : public ::testing::TestWithParam<std::string> {};

TEST_P(McapRoundTrip, EveryMessageMetadataAndAttachmentComesBack) {
  std::vector<Written> written;
  Reader reader(sample_file(GetParam(), &written));
  const Summary& s = reader.summary();
  EXPECT_TRUE(s.indexed);
  EXPECT_TRUE(reader.problems().empty());
  EXPECT_EQ(s.header.profile, "ros2");
  EXPECT_EQ(s.statistics.message_count, 300u);
  EXPECT_EQ(s.statistics.schema_count, 2u);
  EXPECT_EQ(s.statistics.channel_count, 3u);
  EXPECT_EQ(s.statistics.message_start_time, 0u);
  EXPECT_EQ(s.statistics.message_end_time, 299'000'000u);
  EXPECT_EQ(s.statistics.channel_message_counts.at(1), 100u);
  EXPECT_GT(s.statistics.chunk_count, 10u);
  EXPECT_EQ(s.chunk_indexes.size(), s.statistics.chunk_count);
  for (const ChunkIndex& c : s.chunk_indexes) EXPECT_EQ(c.compression, GetParam());
  EXPECT_EQ(s.channels.at(0).metadata.at("node"), "truth");
  EXPECT_EQ(s.schemas.at(2).name, "sensor_msgs/msg/Image");

  EXPECT_TRUE(same(read_all(reader), written));

  // By topic and time range [100 ms, 200 ms).
  MessageFilter filter;
  filter.topics = {"/camera/frame/left"};
  filter.start = 100'000'000;
  filter.end = 200'000'000;
  std::vector<Written> expected;
  for (const Written& w : written)
    if (w.channel == 1 && w.log_time >= 100'000'000 && w.log_time < 200'000'000) expected.push_back(w);
  EXPECT_EQ(expected.size(), 34u);  // i = 100, 103, ..., 199
  EXPECT_TRUE(same(read_all(reader, filter), expected));

  const auto metadata = reader.metadata();
  ASSERT_EQ(metadata.size(), 1u);
  EXPECT_EQ(metadata[0].name, "kestrel");
  EXPECT_EQ(metadata[0].metadata.at("graph"), "nodes: []");
  const auto attachments = reader.attachments();
  ASSERT_EQ(attachments.size(), 1u);
  EXPECT_EQ(attachments[0].data, bytes_of("fx: 452\n"));
  EXPECT_NE(attachments[0].crc, 0u);

  const Verification v = reader.verify();
  EXPECT_TRUE(v.data_section_crc_present);
  EXPECT_TRUE(v.summary_crc_present);
  EXPECT_EQ(v.chunks, s.statistics.chunk_count);
  EXPECT_EQ(v.chunks_with_crc, v.chunks);
  EXPECT_EQ(v.attachments_with_crc, 1u);
}

INSTANTIATE_TEST_SUITE_P(Compressions, McapRoundTrip, ::testing::Values("", "zstd", "lz4"),
                         [](const auto& info) { return info.param.empty() ? std::string("none") : info.param; });

TEST(McapWriter, TheSameCallsGiveTheSameBytes) {
  EXPECT_EQ(sample_file("zstd"), sample_file("zstd"));
  EXPECT_EQ(sample_file("lz4"), sample_file("lz4"));
  EXPECT_NE(sample_file("zstd"), sample_file("lz4"));
}

TEST(McapWriter, CompressesAndChecksumsAsTheSpecificationSays) {
  const Bytes file = sample_file("zstd");
  ASSERT_GT(file.size(), 16u);
  EXPECT_TRUE(std::equal(std::begin(kMagic), std::end(kMagic), file.begin()));
  EXPECT_TRUE(std::equal(std::begin(kMagic), std::end(kMagic), file.end() - 8));
  // The footer: opcode 2, length 20, summary_start, summary_offset_start, summary_crc over the
  // summary through the footer's summary_offset_start, computed here with zlib directly.
  const std::size_t footer = file.size() - 8 - 29;
  EXPECT_EQ(file[footer], 0x02);
  std::uint64_t summary_start = 0;
  for (int i = 0; i < 8; ++i) summary_start |= std::uint64_t{file[footer + 9 + static_cast<std::size_t>(i)]} << (8 * i);
  std::uint32_t crc = 0;
  for (int i = 0; i < 4; ++i) crc |= std::uint32_t{file[footer + 25 + static_cast<std::size_t>(i)]} << (8 * i);
  const auto covered = static_cast<uInt>(footer + 25 - summary_start);
  EXPECT_EQ(crc, static_cast<std::uint32_t>(::crc32(0, file.data() + summary_start, covered)));
  // zstd makes the repetitive payloads smaller than storing them.
  EXPECT_LT(file.size(), sample_file("").size());
}

TEST(McapReader, AFileCutShortYieldsEveryCompleteChunk) {
  std::vector<Written> written;
  const Bytes whole = sample_file("zstd", &written);
  const Reader indexed{Bytes(whole)};
  // Cut in the middle of the sixth chunk: the first five chunks' messages come back, by streaming.
  const ChunkIndex& sixth = indexed.summary().chunk_indexes.at(5);
  const Bytes cut(whole.begin(),
                  whole.begin() + static_cast<std::ptrdiff_t>(sixth.chunk_start_offset + sixth.chunk_length / 2));
  Reader reader{Bytes(cut)};
  EXPECT_FALSE(reader.summary().indexed);
  ASSERT_FALSE(reader.problems().empty());
  EXPECT_THAT(reader.problems().back(), ::testing::HasSubstr("ends inside a record"));
  const auto got = read_all(reader);
  std::vector<Written> expected;
  for (const Written& w : written)
    if (w.log_time <= indexed.summary().chunk_indexes.at(4).message_end_time) expected.push_back(w);
  EXPECT_TRUE(same(got, expected));
  EXPECT_EQ(reader.summary().statistics.message_count, expected.size());
  EXPECT_EQ(reader.summary().statistics.chunk_count, 5u);
}

TEST(McapReader, EveryCutOfAFileReadsOrFailsWithAFormatError) {
  const Bytes whole = sample_file("lz4", nullptr, 600);
  for (std::size_t cut = 0; cut < whole.size(); cut += 13) {
    try {
      Reader reader{Bytes(whole.begin(), whole.begin() + static_cast<std::ptrdiff_t>(cut))};
      std::size_t n = 0;
      reader.read_messages({}, [&](const MessageView&) { ++n; });
      EXPECT_LE(n, 300u);
    } catch (const FormatError&) {
      EXPECT_LT(cut, 8u + 9u + 30u) << "only a file cut before its Header ends may be refused, cut at " << cut;
    }
  }
}

TEST(McapReader, CorruptBytesAreFoundByTheirCrc) {
  const Bytes whole = sample_file("");
  const Reader indexed{Bytes(whole)};
  // A payload byte of the third chunk (uncompressed, so the flip survives to the CRC check).
  Bytes bad = whole;
  const ChunkIndex& third = indexed.summary().chunk_indexes.at(2);
  bad[third.chunk_start_offset + third.chunk_length - 5] ^= 0x40;
  Reader reader{std::move(bad)};
  try {
    read_all(reader);
    FAIL() << "a corrupt chunk was read";
  } catch (const FormatError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("CRC mismatch"));
    EXPECT_THAT(e.what(), ::testing::HasSubstr(std::to_string(third.chunk_start_offset)));
  }
  // A byte of the summary: the summary is not trusted, the file is streamed instead.
  Bytes bad_summary = whole;
  bad_summary[whole.size() - 8 - 29 - 3] ^= 0x01;
  Reader streamed{std::move(bad_summary)};
  EXPECT_FALSE(streamed.summary().indexed);
  EXPECT_THAT(streamed.problems().front(), ::testing::HasSubstr("CRC"));
  EXPECT_EQ(read_all(streamed).size(), 300u);
  // A byte of the metadata record, in the data section outside any chunk: verify() finds it.
  Bytes bad_data = whole;
  const MetadataIndex& meta = indexed.summary().metadata_indexes.at(0);
  bad_data[meta.offset + meta.length - 3] ^= 0x01;
  Reader data_reader{std::move(bad_data)};
  EXPECT_THROW(data_reader.verify(), FormatError);
}

TEST(McapReader, RefusesWhatIsNotMcap) {
  EXPECT_THROW(Reader{Bytes{}}, FormatError);
  EXPECT_THROW(Reader{bytes_of("GIF89a, not a recording at all")}, FormatError);
  Bytes header_missing(std::begin(kMagic), std::end(kMagic));
  header_missing.push_back(0x05);
  EXPECT_THROW(Reader{std::move(header_missing)}, FormatError);
  EXPECT_THROW(Reader(std::filesystem::path("/nonexistent/run.mcap")), Error);
  // A chunk claiming more than the reader will hold is refused, not allocated.
  ReaderOptions small;
  small.max_record_bytes = 4000;  // the summary fits, a 5000-byte chunk does not
  Reader limited(sample_file("zstd", nullptr, 5000), small);
  EXPECT_THROW(read_all(limited), FormatError);
}

TEST(McapWriter, RefusesBadOptionsAndUnknownIds) {
  std::ostringstream out;
  WriterOptions bad;
  bad.compression = "gzip";
  EXPECT_THROW(Writer(out, bad), Error);
  bad = WriterOptions{};
  bad.chunk_size = 0;
  EXPECT_THROW(Writer(out, bad), Error);
  Writer writer(out, WriterOptions{});
  EXPECT_THROW(writer.add_channel(3, "/x", "cdr"), Error);
  EXPECT_THROW(writer.write_message(0, 0, 0, {}), Error);
  EXPECT_THROW(Writer("/nonexistent/dir/run.mcap", WriterOptions{}), Error);
}
