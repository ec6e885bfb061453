#pragma once
// What `mcap_source` replays: for each of its ports, the channels of a recording that carry the
// port's message type under the chosen topic ("/camera/frame" for a StereoFrame: its /left,
// /right and camera info channels), read back through the ROS 2 mapping's decoders.
#include <deque>
#include <filesystem>
#include <functional>
#include <kestrel/mcap/reader.hpp>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "kestrel/ros2_messages/message_mapping.hpp"

namespace kestrel::replay {

/// One port fed from the recording.
struct ReplayedPort {
  std::string port;          ///< the node's output
  std::string kestrel_type;  ///< "kestrel.StereoFrame"
  std::string topic;         ///< the recorded output's topic, "/camera/frame"
  /// The full topic of each of the decoder's inputs, in its order, where they are not named after
  /// `topic` (a ROS 2 bag's /stereo/left/image_rect and /stereo/left/camera_info); empty: topic +
  /// each input's suffix.
  std::vector<std::string> input_topics = {};
};

class RecordedChannels {
 public:
  /// Opens the file and finds, for each port, the channels its decoder needs. Throws Error naming
  /// the topic and what the file holds when one is missing or carries another type.
  RecordedChannels(const std::filesystem::path& file, std::vector<ReplayedPort> ports);

  /// Calls `publish(port index, message)` for every kestrel message whose parts were logged in
  /// [from, to), in log-time order.
  void replay(mcap::Timestamp from, mcap::Timestamp to,
              const std::function<void(std::size_t, std::shared_ptr<const void>)>& publish);

  /// Log time of the last message to replay, for the end of the stream.
  mcap::Timestamp end_time() const { return end_time_; }
  /// The rate of the busiest port's channel over the recording's first second, rounded to
  /// 1/1000 Hz: a recording of a 30 Hz camera gives exactly 30, so that ticks fall on the
  /// recorded times. 0 if it cannot tell.
  double busiest_rate_hz() const { return busiest_rate_hz_; }
  std::uint64_t unpaired() const;
  const std::vector<ReplayedPort>& ports() const { return ports_; }
  const std::vector<std::string>& problems() const { return reader_.problems(); }

 private:
  struct Route {
    std::size_t port;
    std::size_t input;  // of the port's decoder
    ros2::ChannelMetadata metadata;
  };
  void feed(const mcap::Message& m, const std::function<void(std::size_t, std::shared_ptr<const void>)>& publish);

  mcap::Reader reader_;
  std::deque<mcap::Message> unindexed_;  // a file without a summary: its replayed messages, in file order
  std::vector<ReplayedPort> ports_;
  std::vector<std::unique_ptr<ros2::Decoder>> decoders_;
  std::map<std::uint16_t, Route> routes_;  // channel id -> where its messages go
  std::vector<std::string> topics_;
  mcap::Timestamp end_time_ = 0;
  double busiest_rate_hz_ = 0.0;
};

}  // namespace kestrel::replay
