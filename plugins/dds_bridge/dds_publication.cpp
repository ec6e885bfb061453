#include "dds_publication.hpp"

#include <kestrel/dds/ros2_names.hpp>

namespace kestrel::dds_bridge {

DdsPublication::DdsPublication(const dds::Participant& participant, dds::QosTable qos, std::string prefix, bool derived)
    : participant_(participant), qos_(std::move(qos)), prefix_(std::move(prefix)), derived_(derived) {}

DdsPublication::Channel& DdsPublication::channel(const ros2::ChannelSpec& spec, const ros2::ChannelMetadata& metadata) {
  // /tf is the one tree every node adds to: no prefix, as in ROS 2.
  const std::string topic = spec.topic == "/tf" ? spec.topic : prefix_ + spec.topic;
  auto it = channels_.find(topic);
  if (it == channels_.end()) {
    Channel c;
    c.derived = spec.derived;
    c.writer = std::make_unique<dds::Writer>(participant_, dds::ros2_dds_topic(topic), dds::ros2_dds_type(spec.schema),
                                             qos_.for_topic(topic), metadata);
    it = channels_.emplace(topic, std::move(c)).first;
  } else if (!spec.derived) {
    it->second.writer->set_metadata(metadata);
  }
  return it->second;
}

void DdsPublication::publish(const Envelope& e) {
  const std::string type(e.type);
  if (!ros2::can_encode(type)) {
    ++unpublished_[type];
    return;
  }
  const std::string topic = topic_of(e);
  auto known = specs_.find(topic);
  if (known == specs_.end()) known = specs_.emplace(topic, ros2::channels_for(type, topic)).first;
  const ros2::Encoded encoded = ros2::encode(type, e.payload.get(), topic);
  for (const auto& m : encoded.messages) {
    const ros2::ChannelSpec& spec = known->second.at(m.channel);
    if (spec.derived && !derived_) continue;
    ros2::ChannelMetadata metadata = spec.derived ? ros2::ChannelMetadata{} : encoded.metadata;
    if (clock_origin_ns_) metadata[kClockOriginKey] = std::to_string(*clock_origin_ns_);
    Channel& c = channel(spec, metadata);
    c.writer->write(m.cdr);
    ++by_topic_[c.writer->topic().substr(2)];
    ++samples_;
    bytes_ += m.cdr.size();
  }
}

std::uint64_t DdsPublication::unpublished() const {
  std::uint64_t n = 0;
  for (const auto& [_, count] : unpublished_) n += count;
  return n;
}

void DdsPublication::report(ReportSection& section) const {
  std::map<std::string, std::uint64_t> readers;
  for (const auto& [topic, c] : channels_) readers[topic] = c.writer->matched_readers();
  section.quantity("published", samples_, "samples")
      .quantity("published_bytes", bytes_, "B")
      .quantity("published_by_topic", by_topic_)
      .quantity("matched_readers", readers)
      .metric("unpublished", unpublished_, "messages", Better::lower);
}

}  // namespace kestrel::dds_bridge
