#include "kestrel/dds/reader.hpp"

#include <dds/dds.h>
#include <fmt/format.h>

#include <array>
#include <kestrel/error.hpp>
#include <thread>

#include "cyclone.hpp"
#include "kestrel/dds/cdr_padding.hpp"
#include "raw_cdr_type.hpp"

namespace kestrel::dds {

Reader::Reader(const Participant& participant, const std::string& dds_topic, const std::string& dds_type,
               const Qos& qos)
    : topic_(dds_topic) {
  topic_entity_ = detail::create_raw_topic(participant.entity(), dds_topic, dds_type);
  auto q = detail::to_cyclone(qos);
  reader_ = dds_create_reader(participant.entity(), topic_entity_, q.get(), nullptr);
  if (reader_ < 0) {
    dds_delete(topic_entity_);
    detail::check(reader_, fmt::format("creating a DDS reader of '{}' ({})", dds_topic, to_string(qos)));
  }
}

Reader::~Reader() {
  dds_delete(reader_);
  dds_delete(topic_entity_);
}

std::size_t Reader::take(const std::function<void(ReceivedSample&&)>& each) {
  constexpr std::size_t kBatch = 32;
  std::size_t taken = 0;
  for (;;) {
    std::array<ddsi_serdata*, kBatch> data{};
    std::array<dds_sample_info_t, kBatch> info{};
    const dds_return_t n = dds_takecdr(reader_, data.data(), kBatch, info.data(), DDS_ANY_STATE);
    detail::check(n, fmt::format("taking samples of '{}'", topic_));
    for (dds_return_t i = 0; i < n; ++i) {
      if (info[i].valid_data) {
        ReceivedSample sample{static_cast<detail::RawSerdata*>(data[i])->bytes, info[i].source_timestamp,
                              info[i].publication_handle};
        strip_cdr_padding(sample.cdr);  // the writer's, not the message's
        ++taken;
        ddsi_serdata_unref(data[i]);
        data[i] = nullptr;
        each(std::move(sample));
      } else {
        ddsi_serdata_unref(data[i]);
      }
    }
    if (static_cast<std::size_t>(n) < kBatch) return taken;
  }
}

WriterMetadata Reader::writer_metadata(std::uint64_t writer) const {
  dds_builtintopic_endpoint_t* endpoint = dds_get_matched_publication_data(reader_, writer);
  if (endpoint == nullptr) return {};
  WriterMetadata out;
  void* data = nullptr;
  size_t size = 0;
  if (endpoint->qos != nullptr && dds_qget_userdata(endpoint->qos, &data, &size) && data != nullptr) {
    out = decode_metadata(std::string_view(static_cast<const char*>(data), size));
    dds_free(data);
  }
  dds_builtintopic_free_endpoint(endpoint);
  return out;
}

std::size_t Reader::matched_writers() const {
  dds_subscription_matched_status_t status{};
  detail::check(dds_get_subscription_matched_status(reader_, &status), "reading a reader's matches");
  return status.current_count;
}

bool Reader::wait_for_writers(std::size_t count, std::chrono::milliseconds timeout) const {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (matched_writers() < count) {
    if (std::chrono::steady_clock::now() >= deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return true;
}

std::uint64_t Reader::lost_samples() const {
  dds_sample_lost_status_t status{};
  detail::check(dds_get_sample_lost_status(reader_, &status), "reading a reader's lost samples");
  return status.total_count;
}

}  // namespace kestrel::dds
