#pragma once
// The records of an MCAP file (https://mcap.dev/spec, major version 0), as plain values.
//
// Field names and orders follow the specification's tables. Maps are ordered (std::map), so that
// a writer given the same records writes the same bytes.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "kestrel/error.hpp"

namespace kestrel::mcap {

using Bytes = std::vector<std::uint8_t>;
using Timestamp = std::uint64_t;  ///< nanoseconds; kestrel writes the run's clock
using KeyValues = std::map<std::string, std::string>;

/// A file that breaks the specification: a bad magic, a record cut short, a CRC that does not
/// match, a chunk that does not decompress. The message says what and at which byte.
class FormatError : public Error {
 public:
  using Error::Error;
};

/// The leading and trailing magic: 0x89 "MCAP" '0' "\r\n".
inline constexpr std::uint8_t kMagic[8] = {0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n'};

enum class Opcode : std::uint8_t {
  header = 0x01,
  footer = 0x02,
  schema = 0x03,
  channel = 0x04,
  message = 0x05,
  chunk = 0x06,
  message_index = 0x07,
  chunk_index = 0x08,
  attachment = 0x09,
  attachment_index = 0x0A,
  statistics = 0x0B,
  metadata = 0x0C,
  metadata_index = 0x0D,
  summary_offset = 0x0E,
  data_end = 0x0F,
};

/// The record's name as the specification spells it ("Chunk Index"), or "opcode 0xNN".
std::string opcode_name(std::uint8_t opcode);

struct Header {
  std::string profile;  ///< "ros2" for kestrel's recordings
  std::string library;
};

struct Footer {
  std::uint64_t summary_start = 0;         ///< 0: no summary section
  std::uint64_t summary_offset_start = 0;  ///< 0: no summary offset section
  std::uint32_t summary_crc = 0;           ///< 0: not available
};

struct Schema {
  std::uint16_t id = 0;  ///< never 0
  std::string name;      ///< "sensor_msgs/msg/Image"
  std::string encoding;  ///< "ros2msg", "jsonschema", ... ("" = no schema)
  Bytes data;
};

struct Channel {
  std::uint16_t id = 0;
  std::uint16_t schema_id = 0;  ///< 0: no schema
  std::string topic;
  std::string message_encoding;  ///< "cdr", "json", ...
  KeyValues metadata;
};

struct Message {
  std::uint16_t channel_id = 0;
  std::uint32_t sequence = 0;
  Timestamp log_time = 0;
  Timestamp publish_time = 0;
  Bytes data;
};

struct Chunk {
  Timestamp message_start_time = 0;
  Timestamp message_end_time = 0;
  std::uint64_t uncompressed_size = 0;
  std::uint32_t uncompressed_crc = 0;  ///< 0: not available
  std::string compression;             ///< "", "zstd" or "lz4"
  Bytes records;                       ///< compressed with `compression`
};

struct MessageIndex {
  std::uint16_t channel_id = 0;
  /// log_time and offset of each message, from the start of the uncompressed chunk records.
  std::vector<std::pair<Timestamp, std::uint64_t>> records;
};

struct ChunkIndex {
  Timestamp message_start_time = 0;
  Timestamp message_end_time = 0;
  std::uint64_t chunk_start_offset = 0;  ///< from the start of the file
  std::uint64_t chunk_length = 0;        ///< the whole record, opcode and length included
  std::map<std::uint16_t, std::uint64_t> message_index_offsets;
  std::uint64_t message_index_length = 0;
  std::string compression;
  std::uint64_t compressed_size = 0;
  std::uint64_t uncompressed_size = 0;
};

struct Attachment {
  Timestamp log_time = 0;
  Timestamp create_time = 0;
  std::string name;
  std::string media_type;  ///< MIME type
  Bytes data;
  std::uint32_t crc = 0;  ///< of the preceding fields; 0: not available
};

struct AttachmentIndex {
  std::uint64_t offset = 0;
  std::uint64_t length = 0;
  Timestamp log_time = 0;
  Timestamp create_time = 0;
  std::uint64_t data_size = 0;
  std::string name;
  std::string media_type;
};

struct Statistics {
  std::uint64_t message_count = 0;
  std::uint16_t schema_count = 0;
  std::uint32_t channel_count = 0;
  std::uint32_t attachment_count = 0;
  std::uint32_t metadata_count = 0;
  std::uint32_t chunk_count = 0;
  Timestamp message_start_time = 0;
  Timestamp message_end_time = 0;
  std::map<std::uint16_t, std::uint64_t> channel_message_counts;
};

struct Metadata {
  std::string name;
  KeyValues metadata;
};

struct MetadataIndex {
  std::uint64_t offset = 0;
  std::uint64_t length = 0;
  std::string name;
};

struct SummaryOffset {
  std::uint8_t group_opcode = 0;
  std::uint64_t group_start = 0;
  std::uint64_t group_length = 0;
};

struct DataEnd {
  std::uint32_t data_section_crc = 0;  ///< 0: not available
};

}  // namespace kestrel::mcap
