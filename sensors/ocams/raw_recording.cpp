#include "raw_recording.hpp"

#include <kestrel/error.hpp>
#include <kestrel/ros2/cdr.hpp>
#include <kestrel/ros2/definitions.hpp>

#include "raw_frame.hpp"

namespace kestrel::ocams {

namespace {

constexpr const char* kSchema = "sensor_msgs/msg/Image";
constexpr const char* kEncoding = "8UC2";                   // each pixel: the right eye's byte, then the left's
constexpr const char* kFormatKey = "kestrel.ocams.format";  // "WIDTHxHEIGHT@FPS"

std::string format_text(const RawFormat& f) {
  return std::to_string(f.width) + "x" + std::to_string(f.height) + "@" + std::to_string(f.fps);
}

RawFormat parse_format(const std::string& text, const std::string& file) {
  RawFormat f;
  char x = 0, at = 0;
  std::istringstream in(text);
  if (!(in >> f.width >> x >> f.height >> at >> f.fps) || x != 'x' || at != '@' || f.width <= 0 || f.height <= 0)
    throw Error(file + ": the raw channel's format '" + text + "' is not WIDTHxHEIGHT@FPS");
  return f;
}

mcap::Bytes bytes_of(const std::string& s) { return mcap::Bytes(s.begin(), s.end()); }

}  // namespace

RawRecorder::RawRecorder(const std::filesystem::path& file, RawRecordingOptions options)
    : options_(std::move(options)),
      writer_(
          [&] {
            std::error_code ec;
            if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path(), ec);
            return file;
          }(),
          mcap::WriterOptions{"ros2", "kestrel", options_.compression, 0, 4u << 20}) {
  const std::string& text = ros2::schema_text(kSchema);
  const auto schema =
      writer_.add_schema(kSchema, "ros2msg", {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()});
  channel_ =
      writer_.add_channel(schema, options_.topic, "cdr",
                          {{kFormatKey, format_text(options_.format)}, {"kestrel.ocams.device", options_.device}});
  if (!options_.left_yaml.empty())
    writer_.write_attachment(mcap::Attachment{0, 0, "left.yaml", "application/yaml", bytes_of(options_.left_yaml), 0});
  if (!options_.right_yaml.empty())
    writer_.write_attachment(
        mcap::Attachment{0, 0, "right.yaml", "application/yaml", bytes_of(options_.right_yaml), 0});
  if (options_.queue_frames > 0) {
    queue_.emplace(options_.queue_frames);
    thread_ = std::thread([this] {
      try {
        while (auto item = queue_->pop()) write_now(*item);
      } catch (const std::exception& e) {
        thread_error_ = e.what();
        while (queue_->pop()) {
        }
      }
    });
  }
}

RawRecorder::~RawRecorder() {
  try {
    finish();
  } catch (const std::exception&) {
    // finish() already reported it to whoever called it; a destructor must not throw
  }
}

void RawRecorder::write(std::span<const std::uint8_t> raw, Time stamp, std::uint64_t frame_index) {
  if (raw.size() != raw_frame_bytes(options_.format.width, options_.format.height))
    throw Error("a raw frame of " + std::to_string(raw.size()) + " bytes for a recording of " +
                format_text(options_.format));
  Item item{{raw.begin(), raw.end()}, stamp, frame_index};
  if (queue_)
    queue_->push(std::move(item));
  else
    write_now(item);
}

void RawRecorder::write_now(const Item& item) {
  ros2::CdrWriter w;
  // std_msgs/Header: builtin_interfaces/Time as whole seconds and nanoseconds
  const std::int64_t ns = item.stamp.count();
  const std::int64_t sec = ns >= 0 ? ns / 1'000'000'000 : -((-ns + 999'999'999) / 1'000'000'000);
  w.i32(static_cast<std::int32_t>(sec));
  w.u32(static_cast<std::uint32_t>(ns - sec * 1'000'000'000));
  w.string("ocams");
  w.u32(static_cast<std::uint32_t>(options_.format.height));
  w.u32(static_cast<std::uint32_t>(options_.format.width));
  w.string(kEncoding);
  w.u8(0);
  w.u32(static_cast<std::uint32_t>(2 * options_.format.width));
  w.bytes(item.raw);
  const auto at = static_cast<mcap::Timestamp>(std::max<std::int64_t>(0, ns));
  writer_.write_message(channel_, at, at, w.take(), static_cast<std::uint32_t>(item.index));
  ++written_;
}

void RawRecorder::finish() {
  if (finished_) return;
  finished_ = true;
  if (queue_) {
    queue_->close();
    thread_.join();
  }
  writer_.write_metadata(mcap::Metadata{
      "kestrel.ocams.capture", {{"frames", std::to_string(written_)}, {"dropped", std::to_string(dropped())}}});
  writer_.finish();
  if (!thread_error_.empty()) throw Error("writing raw frames: " + thread_error_);
}

RawReader::RawReader(const std::filesystem::path& file, const std::string& topic) : reader_(file) {
  const auto& summary = reader_.summary();
  std::string found;
  for (const auto& [id, channel] : summary.channels) {
    const auto format = channel.metadata.find(kFormatKey);
    if (format == channel.metadata.end() || (!topic.empty() && channel.topic != topic)) continue;
    if (!found.empty())
      throw Error(file.string() + " has raw oCamS channels " + found + " and " + channel.topic + ": choose one");
    found = channel.topic;
    channel_ = id;
    format_ = parse_format(format->second, file.string());
  }
  if (found.empty()) {
    std::string have;
    for (const auto& [id, channel] : summary.channels) have += (have.empty() ? "" : ", ") + channel.topic;
    throw Error(file.string() + " has no raw oCamS channel" + (topic.empty() ? "" : " " + topic) +
                " (it has: " + (have.empty() ? "nothing" : have) + "); record one with ocams_stereo's raw_file");
  }
  topic_ = found;
  for (const auto& a : reader_.attachments()) {
    if (a.name == "left.yaml") left_yaml_ = std::string(a.data.begin(), a.data.end());
    if (a.name == "right.yaml") right_yaml_ = std::string(a.data.begin(), a.data.end());
  }
  if (summary.indexed) {
    start_ = summary.statistics.message_start_time;
    end_ = summary.statistics.message_end_time;
    const auto n = summary.statistics.channel_message_counts.find(channel_);
    count_ = n == summary.statistics.channel_message_counts.end() ? 0 : n->second;
    return;
  }
  // Cut short: no index to read a window by. The frames of every complete chunk, held in memory.
  mcap::MessageFilter all;
  all.topics = {topic_};
  bool first = true;
  reader_.read_messages(all, [&](const mcap::MessageView& m) {
    if (m.channel.id != channel_) return;
    unindexed_.push_back(decode(m.message));
    if (first) start_ = m.message.log_time;
    first = false;
    end_ = std::max(end_, m.message.log_time);
  });
  count_ = unindexed_.size();
}

RawRecord RawReader::decode(const mcap::Message& m) const {
  ros2::CdrReader r(m.data);
  RawRecord out;
  const std::int64_t sec = r.i32();
  const std::int64_t nanosec = r.u32();
  out.stamp = Time(sec * 1'000'000'000 + nanosec);
  r.string();
  const std::uint32_t height = r.u32(), width = r.u32();
  const std::string encoding = r.string();
  r.u8();
  const std::uint32_t step = r.u32();
  out.raw = r.bytes();
  if (encoding != kEncoding || static_cast<int>(width) != format_.width || static_cast<int>(height) != format_.height ||
      step != 2 * width || out.raw.size() != raw_frame_bytes(format_.width, format_.height))
    throw Error("raw frame " + std::to_string(m.sequence) + " on " + topic_ + " is " + encoding + " " +
                std::to_string(width) + "x" + std::to_string(height) + " with " + std::to_string(out.raw.size()) +
                " bytes, not a " + format_text(format_) + " raw frame");
  out.frame_index = m.sequence;
  return out;
}

void RawReader::read(mcap::Timestamp from, mcap::Timestamp to, const std::function<void(const RawRecord&)>& each) {
  if (!reader_.summary().indexed) {
    while (!unindexed_.empty() &&
           static_cast<mcap::Timestamp>(std::max<std::int64_t>(0, unindexed_.front().stamp.count())) < to) {
      each(unindexed_.front());
      unindexed_.pop_front();
    }
    return;
  }
  mcap::MessageFilter window;
  window.start = from;
  window.end = to;
  window.topics = {topic_};
  reader_.read_messages(window, [&](const mcap::MessageView& m) {
    if (m.channel.id == channel_) each(decode(m.message));
  });
}

}  // namespace kestrel::ocams
