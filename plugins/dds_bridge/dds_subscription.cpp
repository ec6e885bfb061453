#include "dds_subscription.hpp"

#include <algorithm>
#include <kestrel/dds/ros2_names.hpp>
#include <kestrel/error.hpp>

namespace kestrel::dds_bridge {

DdsSubscription::DdsSubscription(const dds::Participant& participant, const dds::QosTable& qos,
                                 std::vector<SubscribedPort> ports)
    : ports_(std::move(ports)) {
  for (std::size_t p = 0; p < ports_.size(); ++p) {
    decoders_.push_back(ros2::make_decoder(ports_[p].kestrel_type));
    if (!decoders_.back()) throw Error("messages of type " + ports_[p].kestrel_type + " cannot be read from DDS");
    const auto specs = decoders_.back()->inputs();
    for (std::size_t i = 0; i < specs.size(); ++i) {
      Input in{p, i, ports_[p].topic + specs[i].topic, nullptr};
      in.reader = std::make_unique<dds::Reader>(participant, dds::ros2_dds_topic(in.topic),
                                                dds::ros2_dds_type(specs[i].schema), qos.for_topic(in.topic));
      inputs_.push_back(std::move(in));
    }
  }
}

void DdsSubscription::take(Logger& log, const Publish& publish) {
  // Everything waiting on every topic, fed in the order it was written: the parts of one message
  // (a frame's images and camera infos) meet in its decoder as they would from a recording, however
  // many messages came at once.
  struct Arrived {
    std::size_t input;
    dds::ReceivedSample sample;
  };
  std::vector<Arrived> arrived;
  for (std::size_t i = 0; i < inputs_.size(); ++i) {
    Input& in = inputs_[i];
    if (!in.matched && in.reader->matched_writers() > 0) in.matched = true;
    in.reader->take([&](dds::ReceivedSample&& sample) { arrived.push_back({i, std::move(sample)}); });
  }
  std::stable_sort(arrived.begin(), arrived.end(), [](const Arrived& a, const Arrived& b) {
    return a.sample.source_time_ns < b.sample.source_time_ns;
  });
  for (Arrived& a : arrived) {
    Input& in = inputs_[a.input];
    ++samples_;
    std::shared_ptr<const void> message;
    // A writer's metadata is read once: it is fixed for the writer's life (its clock's origin), and
    // asking the discovery data for it costs a lookup and a copy of its QoS per sample.
    // (None found, the writer just gone or not yet known: asked again next time.)
    auto known = writer_metadata_.find(a.sample.writer);
    if (known == writer_metadata_.end()) {
      dds::WriterMetadata found = in.reader->writer_metadata(a.sample.writer);
      if (!found.empty()) known = writer_metadata_.emplace(a.sample.writer, std::move(found)).first;
    }
    static const dds::WriterMetadata kNone;
    const dds::WriterMetadata& metadata = known == writer_metadata_.end() ? kNone : known->second;
    try {
      message = decoders_[in.port]->feed(in.index, a.sample.cdr, in.sequence++, metadata);
    } catch (const std::exception& e) {
      ++bad_samples_;
      if (!warned_[in.topic]) {
        warned_[in.topic] = true;
        log.warn("dropped a sample of {} that does not decode ({}); later ones are counted", in.topic, e.what());
      }
      continue;
    }
    if (!message) continue;
    ++received_[ports_[in.port].port];
    publish(in.port, std::move(message), metadata);
  }
}

bool DdsSubscription::writers_gone() const {
  for (const Input& in : inputs_)
    if (!in.matched || in.reader->matched_writers() > 0) return false;
  return true;
}

std::vector<std::string> DdsSubscription::never_matched() const {
  std::vector<std::string> out;
  for (const Input& in : inputs_)
    if (!in.matched) out.push_back(in.topic);
  return out;
}

void DdsSubscription::report(ReportSection& section) const {
  std::uint64_t lost = 0, unpaired = 0;
  std::map<std::string, std::uint64_t> writers;
  for (const Input& in : inputs_) {
    lost += in.reader->lost_samples();
    writers[in.topic] = in.reader->matched_writers();
  }
  for (const auto& d : decoders_) unpaired += d->unpaired();
  section.quantity("received_samples", samples_, "samples")
      .quantity("received", received_, "messages")
      .quantity("matched_writers", writers)
      .metric("bad_samples", bad_samples_, "samples", Better::lower)
      .metric("lost_samples", lost, "samples", Better::lower)
      .metric("unpaired", unpaired, "samples", Better::lower)
      .info("never_matched", never_matched());
}

}  // namespace kestrel::dds_bridge
