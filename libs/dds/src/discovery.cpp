#include "kestrel/dds/discovery.hpp"

#include <dds/dds.h>

#include <algorithm>
#include <array>
#include <thread>

#include "cyclone.hpp"

namespace kestrel::dds {

Discovery::Discovery(const Participant& participant) : own_guid_(participant.guid()) {
  publications_ =
      detail::check(dds_create_reader(participant.entity(), DDS_BUILTIN_TOPIC_DCPSPUBLICATION, nullptr, nullptr),
                    "reading DDS discovery (publications)");
  subscriptions_ =
      detail::check(dds_create_reader(participant.entity(), DDS_BUILTIN_TOPIC_DCPSSUBSCRIPTION, nullptr, nullptr),
                    "reading DDS discovery (subscriptions)");
}

Discovery::~Discovery() {
  dds_delete(subscriptions_);
  dds_delete(publications_);
}

void Discovery::poll(std::int32_t reader, bool writers) {
  constexpr std::size_t kBatch = 16;
  for (;;) {
    std::array<void*, kBatch> samples{};
    std::array<dds_sample_info_t, kBatch> info{};
    const dds_return_t n = dds_take(reader, samples.data(), info.data(), kBatch, kBatch);
    detail::check(n, "reading DDS discovery");
    for (dds_return_t i = 0; i < n; ++i) {
      const auto* e = static_cast<const dds_builtintopic_endpoint_t*>(samples[i]);
      const std::string key = detail::hex(e->key.v, 16);
      if (!info[i].valid_data || info[i].instance_state != DDS_IST_ALIVE) {
        alive_.erase(key);
        continue;
      }
      const std::string participant = detail::hex(e->participant_key.v, 12);
      if (participant == own_guid_ || e->topic_name == nullptr || e->type_name == nullptr) continue;
      DiscoveredEndpoint endpoint{e->topic_name, e->type_name, writers, {}, participant, {}};
      if (e->qos != nullptr) {
        endpoint.qos = detail::from_cyclone(e->qos);
        void* data = nullptr;
        size_t size = 0;
        if (dds_qget_userdata(e->qos, &data, &size) && data != nullptr) {
          endpoint.metadata = decode_metadata(std::string_view(static_cast<const char*>(data), size));
          dds_free(data);
        }
      }
      alive_[key] = std::move(endpoint);
    }
    if (n > 0) dds_return_loan(reader, samples.data(), n);
    if (static_cast<std::size_t>(n) < kBatch) return;
  }
}

std::vector<DiscoveredEndpoint> Discovery::endpoints() {
  poll(publications_, true);
  poll(subscriptions_, false);
  std::vector<DiscoveredEndpoint> out;
  for (const auto& [key, endpoint] : alive_) out.push_back(endpoint);
  std::stable_sort(out.begin(), out.end(), [](const auto& a, const auto& b) {
    return std::tie(a.dds_topic, a.writer) < std::tie(b.dds_topic, b.writer);
  });
  return out;
}

std::vector<DiscoveredEndpoint> Discovery::wait(
    std::chrono::milliseconds timeout, const std::function<bool(const std::vector<DiscoveredEndpoint>&)>& until) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    auto found = endpoints();
    if (until(found) || std::chrono::steady_clock::now() >= deadline) return found;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

}  // namespace kestrel::dds
