#pragma once
// A reader of one topic that hands over each sample's CDR bytes as they came, for the caller to
// decode with the type it expects (kestrel::ros2_messages) or by its schema (kestrel dds echo).
#include <chrono>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "kestrel/dds/participant.hpp"
#include "kestrel/dds/qos.hpp"
#include "kestrel/dds/writer.hpp"

namespace kestrel::dds {

struct ReceivedSample {
  std::vector<std::uint8_t> cdr;    ///< without the padding the writer added: the message as MCAP holds it
  std::int64_t source_time_ns = 0;  ///< when the writer wrote it (its clock)
  std::uint64_t writer = 0;         ///< the writer's instance handle, for writer_metadata()
};

class Reader {
 public:
  /// Throws kestrel::Error (a bad QoS, a topic already created with another type).
  Reader(const Participant& participant, const std::string& dds_topic, const std::string& dds_type, const Qos& qos);
  ~Reader();
  Reader(const Reader&) = delete;
  Reader& operator=(const Reader&) = delete;

  /// Takes every sample waiting, oldest first; returns how many.
  std::size_t take(const std::function<void(ReceivedSample&&)>& each);
  /// The metadata a matched writer announces (empty when it announces none or is gone).
  WriterMetadata writer_metadata(std::uint64_t writer) const;

  std::size_t matched_writers() const;
  bool wait_for_writers(std::size_t count, std::chrono::milliseconds timeout) const;
  /// Samples the middleware knows it lost on this reader (best effort, or a full history).
  std::uint64_t lost_samples() const;

  const std::string& topic() const { return topic_; }

 private:
  std::string topic_;
  std::int32_t topic_entity_ = 0, reader_ = 0;
};

}  // namespace kestrel::dds
