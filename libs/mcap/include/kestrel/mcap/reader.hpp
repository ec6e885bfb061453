#pragma once
// Reads MCAP files: indexed files through their summary (by time range and topic, in log-time
// order), and files without a usable summary (unindexed, cut short by a crash, a summary whose CRC
// fails) by streaming from the start, in file order. A file cut short still yields every message
// of every complete chunk; what was lost is said in problems().
//
// Every length and offset read from the file is checked before it is used: a bad file gives a
// FormatError that says what and where, never a read out of bounds.
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "kestrel/mcap/records.hpp"

namespace kestrel::mcap {

struct ReaderOptions {
  /// The largest record (uncompressed chunk, attachment) the reader will hold in memory.
  std::uint64_t max_record_bytes = std::uint64_t{1} << 30;
};

struct MessageFilter {
  std::optional<Timestamp> start;   ///< first log time read, inclusive
  std::optional<Timestamp> end;     ///< last log time read, exclusive
  std::vector<std::string> topics;  ///< empty: every topic
};

/// One message as the callback sees it; the references live until the callback returns.
struct MessageView {
  const Channel& channel;
  const Schema* schema;  ///< nullptr when the channel has none
  const Message& message;
};

/// What a file holds, from its summary or, without one, from reading it through.
struct Summary {
  Header header;
  bool indexed = false;  ///< read from a summary section whose CRC matched
  Statistics statistics;
  std::map<std::uint16_t, Schema> schemas;
  std::map<std::uint16_t, Channel> channels;
  std::vector<ChunkIndex> chunk_indexes;
  std::vector<AttachmentIndex> attachment_indexes;
  std::vector<MetadataIndex> metadata_indexes;
};

/// What verify() found: each CRC present was checked.
struct Verification {
  bool data_section_crc_present = false;
  bool summary_crc_present = false;
  std::uint64_t chunks = 0, chunks_with_crc = 0;
  std::uint64_t attachments = 0, attachments_with_crc = 0;
};

class Reader {
 public:
  /// Opens `path` and reads its header and summary (or streams through it when it has no usable
  /// summary). Throws Error if it cannot be read, FormatError if it is not an MCAP file.
  explicit Reader(const std::filesystem::path& path, ReaderOptions options = {});
  /// Reads a file held in memory (tests, fuzzing).
  explicit Reader(Bytes bytes, ReaderOptions options = {});
  ~Reader();
  Reader(const Reader&) = delete;
  Reader& operator=(const Reader&) = delete;

  const Summary& summary() const;

  /// Calls `on_message` for each message that passes `filter`: in log-time order when the file is
  /// indexed (ties in file order), in file order otherwise. Throws FormatError on a corrupt chunk
  /// (a CRC that does not match, data that does not decompress).
  void read_messages(const MessageFilter& filter, const std::function<void(const MessageView&)>& on_message);

  std::vector<Metadata> metadata();
  std::vector<Attachment> attachments();

  /// Reads the whole file and checks every CRC it carries: data section, summary, chunks,
  /// attachments. Throws FormatError at the first that does not match.
  Verification verify();

  /// What did not stop reading but a user should know: a truncated file, a summary not used.
  const std::vector<std::string>& problems() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace kestrel::mcap
