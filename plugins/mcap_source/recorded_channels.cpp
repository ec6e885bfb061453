#include "recorded_channels.hpp"

#include <cmath>
#include <kestrel/error.hpp>
#include <set>

namespace kestrel::replay {

RecordedChannels::RecordedChannels(const std::filesystem::path& file, std::vector<ReplayedPort> ports)
    : reader_(file), ports_(std::move(ports)) {
  const auto& summary = reader_.summary();
  std::map<std::uint16_t, std::uint64_t> counts;
  for (const auto& [id, count] : summary.statistics.channel_message_counts) counts[id] = count;
  std::uint64_t busiest = 0;
  for (std::size_t p = 0; p < ports_.size(); ++p) {
    const ReplayedPort& port = ports_[p];
    decoders_.push_back(ros2::make_decoder(port.kestrel_type));
    if (!decoders_.back()) throw Error("messages of type " + port.kestrel_type + " cannot be replayed");
    const auto inputs = decoders_.back()->inputs();
    if (!port.input_topics.empty() && port.input_topics.size() != inputs.size())
      throw Error("port '" + port.port + "' needs " + std::to_string(inputs.size()) + " topics, not " +
                  std::to_string(port.input_topics.size()));
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      const std::string topic = port.input_topics.empty() ? port.topic + inputs[i].topic : port.input_topics[i];
      bool found = false;
      std::set<std::string> other_types;
      for (const auto& [id, channel] : summary.channels) {
        if (channel.topic != topic) continue;
        const auto schema = summary.schemas.find(channel.schema_id);
        const std::string type = schema == summary.schemas.end() ? "no schema" : schema->second.name;
        if (type != inputs[i].schema || channel.message_encoding != "cdr") {
          other_types.insert(type + " (" + channel.message_encoding + ")");
          continue;
        }
        found = true;
        routes_[id] = Route{p, i, ros2::ChannelMetadata(channel.metadata.begin(), channel.metadata.end())};
        topics_.push_back(topic);
        if (counts[id] > busiest) busiest = counts[id];
      }
      if (!found && inputs[i].optional && other_types.empty()) continue;
      if (!found) {
        std::string have;
        for (const auto& t : other_types) have += (have.empty() ? "" : ", ") + t;
        throw Error(file.string() + " has no channel " + topic + " of " + inputs[i].schema + " (cdr) for port '" +
                    port.port + "'" + (have.empty() ? "; kestrel mcap info lists its channels" : "; it has " + have));
      }
    }
  }
  // The busiest channel's rate, from its log times over the recording's first second: only the
  // chunks of that second are read.
  for (const auto& entry : routes_) {
    const std::uint16_t id = entry.first;
    if (counts[id] != busiest || busiest < 2) continue;
    std::vector<mcap::Timestamp> times;
    mcap::MessageFilter filter;
    filter.start = summary.statistics.message_start_time;
    filter.end = summary.statistics.message_start_time + 1'000'000'000;
    filter.topics = {summary.channels.at(id).topic};
    reader_.read_messages(filter, [&](const mcap::MessageView& m) {
      if (m.channel.id == id) times.push_back(m.message.log_time);
    });
    if (times.size() >= 2 && times.back() > times.front())
      busiest_rate_hz_ = std::round(1e9 * static_cast<double>(times.size() - 1) /
                                    static_cast<double>(times.back() - times.front()) * 1000.0) /
                         1000.0;
    break;
  }
  end_time_ = summary.statistics.message_end_time;
  // Without a summary (a file cut short by a crash) there is no index to read a window by: the
  // replayed channels are read once, in file order, and handed out from memory.
  if (!summary.indexed) {
    mcap::MessageFilter filter;
    filter.topics = topics_;
    end_time_ = 0;
    reader_.read_messages(filter, [&](const mcap::MessageView& m) {
      if (!routes_.count(m.channel.id)) return;
      unindexed_.push_back(m.message);
      end_time_ = std::max(end_time_, m.message.log_time);
    });
  }
}

void RecordedChannels::feed(const mcap::Message& m,
                            const std::function<void(std::size_t, std::shared_ptr<const void>)>& publish) {
  const auto route = routes_.find(m.channel_id);
  if (route == routes_.end()) return;
  auto message = decoders_[route->second.port]->feed(route->second.input, m.data, m.sequence, route->second.metadata);
  if (message) publish(route->second.port, std::move(message));
}

void RecordedChannels::replay(mcap::Timestamp from, mcap::Timestamp to,
                              const std::function<void(std::size_t, std::shared_ptr<const void>)>& publish) {
  if (!reader_.summary().indexed) {
    for (; !unindexed_.empty() && unindexed_.front().log_time < to; unindexed_.pop_front())
      if (unindexed_.front().log_time >= from) feed(unindexed_.front(), publish);
    return;
  }
  mcap::MessageFilter filter;
  filter.start = from;
  filter.end = to;
  filter.topics = topics_;
  reader_.read_messages(filter, [&](const mcap::MessageView& m) { feed(m.message, publish); });
}

std::uint64_t RecordedChannels::unpaired() const {
  std::uint64_t n = 0;
  for (const auto& d : decoders_) n += d->unpaired();
  return n;
}

}  // namespace kestrel::replay
