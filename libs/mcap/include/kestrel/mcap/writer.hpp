#pragma once
// Writes an indexed MCAP file: messages in chunks (compressed with zstd, lz4 or not at all), a
// Message Index after each chunk, and a summary (schemas, channels, statistics, chunk, metadata
// and attachment indexes, summary offsets) whose CRCs a reader can check.
//
// The same calls give the same bytes: nothing in the file comes from the wall clock, the host or
// the order of a hash map. A chunk is written, and flushed, once its records reach `chunk_size`:
// a process that dies loses at most the chunk it was filling.
#include <filesystem>
#include <iosfwd>
#include <memory>
#include <optional>
#include <span>
#include <string>

#include "kestrel/mcap/records.hpp"

namespace kestrel::mcap {

struct WriterOptions {
  std::string profile;                     ///< Header profile: "ros2" for kestrel's recordings
  std::string library = "kestrel";         ///< Header library
  std::string compression = "zstd";        ///< "", "zstd" or "lz4"
  int compression_level = 0;               ///< 0: the library's default
  std::uint64_t chunk_size = 1024 * 1024;  ///< uncompressed bytes of records per chunk
};

class Writer {
 public:
  /// Creates (or truncates) `path` and writes the magic and the Header. Throws Error if the file
  /// cannot be written or an option is invalid.
  Writer(const std::filesystem::path& path, WriterOptions options);
  /// Writes into `out`, which must outlive the writer.
  Writer(std::ostream& out, WriterOptions options);
  /// Finishes the file if finish() was not called; errors are lost then, so call finish().
  ~Writer();
  Writer(const Writer&) = delete;
  Writer& operator=(const Writer&) = delete;

  /// Registers a schema and returns its id (from 1); an identical schema gets the same id.
  std::uint16_t add_schema(const std::string& name, const std::string& encoding, std::span<const std::uint8_t> data);
  /// Registers a channel and returns its id (from 0). `schema_id` 0 means no schema.
  std::uint16_t add_channel(std::uint16_t schema_id, const std::string& topic, const std::string& message_encoding,
                            const KeyValues& metadata = {});
  /// Appends a message; its sequence number is `sequence`, or by default counts the channel's
  /// messages from 0.
  void write_message(std::uint16_t channel_id, Timestamp log_time, Timestamp publish_time,
                     std::span<const std::uint8_t> data, std::optional<std::uint32_t> sequence = std::nullopt);
  /// Metadata and attachments go between chunks, never inside one.
  void write_metadata(const Metadata& metadata);
  void write_attachment(const Attachment& attachment);

  /// Writes the last chunk, Data End, the summary and the footer, and flushes. Idempotent.
  void finish();

  const Statistics& statistics() const;
  const WriterOptions& options() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace kestrel::mcap
