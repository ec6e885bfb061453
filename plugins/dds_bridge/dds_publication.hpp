#pragma once
// The publishing half of `dds_bridge`: each tapped message becomes the ROS 2 messages the
// recording writes (kestrel::ros2_messages), each on a DDS writer of its channel, created when the
// channel's first message comes: topic "rt" + its ROS 2 name, type its mangled ROS 2 type.
#include <kestrel/dds/participant.hpp>
#include <kestrel/dds/qos.hpp>
#include <kestrel/dds/writer.hpp>
#include <kestrel/message.hpp>
#include <kestrel/report_section.hpp>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "kestrel/ros2_messages/message_mapping.hpp"

namespace kestrel::dds_bridge {

class DdsPublication {
 public:
  /// `prefix` goes before every topic ("/vehicle": /vehicle/tracker/tracks); `derived`: also the
  /// channels for viewers (markers, /tf).
  DdsPublication(const dds::Participant& participant, dds::QosTable qos, std::string prefix, bool derived);

  /// Announces, on every writer, the system time (ns since the epoch) at which this run's clock
  /// read zero, so that a reader in another process can put the stamps on its own clock.
  void set_clock_origin(std::int64_t origin_ns) { clock_origin_ns_ = origin_ns; }
  bool has_clock_origin() const { return clock_origin_ns_.has_value(); }

  /// Writes one tapped message. Throws kestrel::Error (a topic name ROS 2 refuses, a refused write).
  void publish(const Envelope& e);

  void report(ReportSection& section) const;
  std::uint64_t samples() const { return samples_; }
  std::uint64_t unpublished() const;

 private:
  struct Channel {
    std::unique_ptr<dds::Writer> writer;
    bool derived = false;
  };
  Channel& channel(const ros2::ChannelSpec& spec, const ros2::ChannelMetadata& metadata);

  const dds::Participant& participant_;
  dds::QosTable qos_;
  std::string prefix_;
  bool derived_;
  std::map<std::string, std::vector<ros2::ChannelSpec>> specs_;  // by output topic
  std::map<std::string, Channel> channels_;                      // by channel topic
  std::map<std::string, std::uint64_t> by_topic_;
  std::map<std::string, std::uint64_t> unpublished_;  // by kestrel type: no ROS 2 mapping
  std::uint64_t samples_ = 0, bytes_ = 0;
  std::optional<std::int64_t> clock_origin_ns_;
};

/// The writer metadata key of a run's clock origin.
inline constexpr const char* kClockOriginKey = "kestrel_clock_origin_ns";

}  // namespace kestrel::dds_bridge
