#pragma once
// The subscribing half of `dds_bridge`: each port fed from a topic reads the DDS topics its
// message type is made of ("/vehicle/camera/frame": its /left, /right and camera infos), with the
// types the ROS 2 mapping gives, and turns what arrives back into kestrel messages. A sample that
// does not decode is counted and dropped.
#include <functional>
#include <kestrel/dds/participant.hpp>
#include <kestrel/dds/qos.hpp>
#include <kestrel/dds/reader.hpp>
#include <kestrel/logger.hpp>
#include <kestrel/report_section.hpp>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "kestrel/ros2_messages/message_mapping.hpp"

namespace kestrel::dds_bridge {

/// One port fed from DDS.
struct SubscribedPort {
  std::string port;          ///< the node's output
  std::string kestrel_type;  ///< "kestrel.Tracks"
  std::string topic;         ///< the ROS 2 topic, "/vehicle/tracker/tracks"
};

class DdsSubscription {
 public:
  /// Throws kestrel::Error (a type that cannot be read back, a topic name ROS 2 refuses).
  DdsSubscription(const dds::Participant& participant, const dds::QosTable& qos, std::vector<SubscribedPort> ports);

  /// Takes what has arrived and calls `publish(port index, message, metadata)` for each kestrel
  /// message complete, in arrival order, with the metadata of the writer of its last part.
  using Publish = std::function<void(std::size_t, std::shared_ptr<const void>, const dds::WriterMetadata&)>;
  void take(Logger& log, const Publish& publish);

  const std::vector<SubscribedPort>& ports() const { return ports_; }
  void report(ReportSection& section) const;
  std::uint64_t bad_samples() const { return bad_samples_; }
  /// Topics no writer ever matched.
  std::vector<std::string> never_matched() const;
  /// Every topic has had a writer, and none has one now: the other side has gone.
  bool writers_gone() const;

 private:
  struct Input {
    std::size_t port;
    std::size_t index;  // of the port's decoder's inputs
    std::string topic;
    std::unique_ptr<dds::Reader> reader;
    std::uint32_t sequence = 0;  // DDS has no per-message sequence: counted here
    bool matched = false;
  };

  std::vector<SubscribedPort> ports_;
  std::vector<std::unique_ptr<ros2::Decoder>> decoders_;
  std::vector<Input> inputs_;
  std::map<std::string, std::uint64_t> received_;  // by port
  std::uint64_t samples_ = 0, bad_samples_ = 0;
  std::map<std::string, bool> warned_;
  std::map<std::uint64_t, dds::WriterMetadata> writer_metadata_;  // by writer instance handle
};

}  // namespace kestrel::dds_bridge
