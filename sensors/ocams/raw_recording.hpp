#pragma once
// Raw oCamS frames in an MCAP file, as they came off USB, so that a field flight can be re-run
// through any graph bit for bit. One channel (`/NODE/raw`) of sensor_msgs/msg/Image with
// encoding 8UC2: each pixel the right eye's Bayer byte, then the left's, with the device clock
// in the first four bytes, exactly the camera's words. The channel's metadata holds the format;
// the attachments `left.yaml` and `right.yaml` the calibration the frames were captured with.
#include <cstdint>
#include <deque>
#include <filesystem>
#include <functional>
#include <kestrel/mcap/reader.hpp>
#include <kestrel/mcap/write_queue.hpp>
#include <kestrel/mcap/writer.hpp>
#include <kestrel/report_section.hpp>
#include <kestrel/time.hpp>
#include <optional>
#include <span>
#include <string>
#include <thread>
#include <vector>

namespace kestrel::ocams {

struct RawFormat {
  int width = 640;
  int height = 480;
  int fps = 30;
};

struct RawRecordingOptions {
  std::string topic = "/camera/raw";
  RawFormat format;
  std::string left_yaml, right_yaml;  ///< camera_info files' text; empty: none attached
  std::string device;                 ///< what captured them, for the metadata
  std::string compression = "lz4";    ///< "", "zstd" or "lz4": raw Bayer compresses little; lz4 costs least
  /// 0: write in the caller's thread (lockstep, tests); otherwise a writer thread behind a queue
  /// of that many frames, which drops (and counts) what finds it full.
  std::size_t queue_frames = 0;
};

class RawRecorder {
 public:
  RawRecorder(const std::filesystem::path& file, RawRecordingOptions options);
  ~RawRecorder();
  RawRecorder(const RawRecorder&) = delete;
  RawRecorder& operator=(const RawRecorder&) = delete;

  /// Records one raw frame (copied) captured at `stamp`.
  void write(std::span<const std::uint8_t> raw, Time stamp, std::uint64_t frame_index);
  /// Writes what is queued and the file's summary. Throws Error if writing failed.
  void finish();

  std::uint64_t written() const { return written_; }
  std::uint64_t dropped() const { return queue_ ? queue_->dropped() : 0; }
  /// Adds "raw": the file, frames written and dropped, to a node's report section.
  void report(ReportSection& section, const std::string& file) const {
    section.info("raw.file", file)
        .quantity("raw.written", written(), "frames")
        .metric("raw.dropped", dropped(), "frames", Better::lower);
  }

 private:
  struct Item {
    std::vector<std::uint8_t> raw;
    Time stamp;
    std::uint64_t index;
  };
  void write_now(const Item& item);

  RawRecordingOptions options_;
  mcap::Writer writer_;
  std::uint16_t channel_ = 0;
  std::optional<mcap::WriteQueue<Item>> queue_;
  std::thread thread_;
  std::string thread_error_;
  std::uint64_t written_ = 0;
  bool finished_ = false;
};

/// One recorded raw frame.
struct RawRecord {
  std::vector<std::uint8_t> raw;
  Time stamp{0};
  std::uint64_t frame_index = 0;
};

class RawReader {
 public:
  /// Opens a raw recording; `topic` empty: its one raw oCamS channel. Throws Error naming what
  /// the file holds when there is no such channel.
  RawReader(const std::filesystem::path& file, const std::string& topic = "");

  const RawFormat& format() const { return format_; }
  const std::string& topic() const { return topic_; }
  /// The calibration files attached at capture, when they were.
  const std::optional<std::string>& left_yaml() const { return left_yaml_; }
  const std::optional<std::string>& right_yaml() const { return right_yaml_; }
  /// Calls `each` for the frames logged in [from, to), in log-time order, read a chunk at a
  /// time. A record that is not a raw frame of the format throws Error.
  void read(mcap::Timestamp from, mcap::Timestamp to, const std::function<void(const RawRecord&)>& each);
  mcap::Timestamp start_time() const { return start_; }
  mcap::Timestamp end_time() const { return end_; }
  std::uint64_t frame_count() const { return count_; }
  /// What could not be read of a file cut short, for the report.
  const std::vector<std::string>& problems() const { return reader_.problems(); }

 private:
  RawRecord decode(const mcap::Message& m) const;

  mcap::Reader reader_;
  RawFormat format_;
  std::string topic_;
  std::uint16_t channel_ = 0;
  std::optional<std::string> left_yaml_, right_yaml_;
  mcap::Timestamp start_ = 0, end_ = 0;
  std::uint64_t count_ = 0;
  std::deque<RawRecord> unindexed_;  // a file without a summary, read once
};

}  // namespace kestrel::ocams
