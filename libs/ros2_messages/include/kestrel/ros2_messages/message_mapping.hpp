#pragma once
// kestrel's messages as ROS 2 messages (docs/recording.md has the table): each kestrel message
// published on an output becomes one or more CDR-encoded ROS 2 messages on channels named after
// that output's topic "/NODE/PORT", plus derived ones for viewers (markers, /tf); a Decoder turns
// the non-derived ones back into the same kestrel message, losing nothing.
//
// Type-erased on purpose: the recorder, the live view and replay handle any message by its type
// name, and this header needs neither OpenCV nor PCL (the library links them privately).
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace kestrel::ros2 {

/// A channel a kestrel message type is written on.
struct ChannelSpec {
  std::string topic;      ///< full topic: the output's, a suffix of it ("/NODE/PORT/left") or "/tf"
  std::string schema;     ///< ROS 2 type, "sensor_msgs/msg/Image"
  bool derived = false;   ///< for viewers only (markers, /tf); replay does not read it
  bool optional = false;  ///< replay goes on without it (another driver's bag may not have it)
};

/// One ROS 2 message made from a kestrel message.
struct Ros2Message {
  std::size_t channel = 0;  ///< index into the type's channels() for that output
  std::vector<std::uint8_t> cdr;
  /// Written as the MCAP message's sequence when set (a StereoFrame's frame_index).
  std::optional<std::uint32_t> sequence;
};

/// Whether kestrel can write messages of `kestrel_type` ("kestrel.StereoFrame").
bool can_encode(std::string_view kestrel_type);
/// The kestrel message types that can be written.
std::vector<std::string> encodable_types();

/// The channels a message of `kestrel_type` published on `topic` ("/NODE/PORT") is written on.
/// Throws kestrel::Error if the type cannot be encoded.
std::vector<ChannelSpec> channels_for(std::string_view kestrel_type, const std::string& topic);

/// Channel metadata (MCAP Channel metadata, string to string).
using ChannelMetadata = std::map<std::string, std::string>;

/// What one kestrel message becomes.
struct Encoded {
  std::vector<Ros2Message> messages;
  /// What the message's non-derived channels must carry as metadata: the few kestrel fields a
  /// ROS 2 type has no place for, which stay the same over a run (a cloud's pixels_per_point). A
  /// writer opens the channels again, on the same topics, when it changes.
  ChannelMetadata metadata;
};

/// The ROS 2 messages of one kestrel message (`message` points at a `kestrel_type`), for the
/// channels channels_for() gave for the same topic. Throws kestrel::Error if it cannot be written
/// (an image of a type ROS 2 has no encoding for, a cloud without points).
Encoded encode(std::string_view kestrel_type, const void* message, const std::string& topic);

/// Turns ROS 2 messages back into kestrel messages of one type.
class Decoder {
 public:
  virtual ~Decoder() = default;
  /// Topic suffixes it reads, relative to the output's topic ("" for the topic itself), with the
  /// ROS 2 type each must carry.
  virtual std::vector<ChannelSpec> inputs() const = 0;
  /// Feeds one message of input `input` (an index into inputs()); returns the kestrel message
  /// once all its parts have arrived (a StereoFrame pairs its images and camera infos by stamp).
  /// Throws kestrel::Error on bytes that are not that type.
  virtual std::shared_ptr<const void> feed(std::size_t input, std::span<const std::uint8_t> cdr, std::uint32_t sequence,
                                           const ChannelMetadata& metadata) = 0;
  /// Parts still waiting for their partners, for the report.
  virtual std::uint64_t unpaired() const { return 0; }
};

/// A decoder for `kestrel_type`, or nullptr if it cannot be read back.
std::unique_ptr<Decoder> make_decoder(std::string_view kestrel_type);

}  // namespace kestrel::ros2
