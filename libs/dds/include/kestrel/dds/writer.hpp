#pragma once
// A writer of one topic whose samples are CDR bytes already made (a ROS 2 message with its
// encapsulation header, as kestrel::ros2_messages encodes it).
#include <chrono>
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "kestrel/dds/participant.hpp"
#include "kestrel/dds/qos.hpp"

namespace kestrel::dds {

/// Key/value pairs a writer announces in discovery (its USER_DATA, "key=value;..."): the few
/// fields a ROS 2 type has no place for, which a kestrel reader needs (a cloud's scale).
using WriterMetadata = std::map<std::string, std::string>;

class Writer {
 public:
  /// Throws kestrel::Error (a bad QoS, a topic already created with another type).
  Writer(const Participant& participant, const std::string& dds_topic, const std::string& dds_type, const Qos& qos,
         const WriterMetadata& metadata = {});
  ~Writer();
  Writer(const Writer&) = delete;
  Writer& operator=(const Writer&) = delete;

  /// Sends one sample, padded to whole 4-byte words as DDS requires (the encapsulation options
  /// say how many bytes were added; readers take them off). Throws kestrel::Error when Cyclone refuses it (bytes not
  /// starting with an encapsulation header, a deleted participant).
  void write(std::span<const std::uint8_t> cdr);
  /// Announces new metadata (discovery carries it to the readers).
  void set_metadata(const WriterMetadata& metadata);
  const WriterMetadata& metadata() const { return metadata_; }

  /// Readers matched now.
  std::size_t matched_readers() const;
  /// Waits until at least `count` readers are matched; false on timeout.
  bool wait_for_readers(std::size_t count, std::chrono::milliseconds timeout) const;

  const std::string& topic() const { return topic_; }

 private:
  std::string topic_;
  std::int32_t topic_entity_ = 0, writer_ = 0;
  WriterMetadata metadata_;
  std::vector<std::uint8_t> padded_;
};

/// "k=v;k2=v2;" (ROS 2's USER_DATA form). Throws kestrel::Error for a key or value holding '=' or ';'.
std::string encode_metadata(const WriterMetadata& metadata);
/// The pairs of "k=v;..."; entries without '=' are skipped.
WriterMetadata decode_metadata(std::string_view text);

}  // namespace kestrel::dds
