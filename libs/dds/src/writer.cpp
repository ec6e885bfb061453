#include "kestrel/dds/writer.hpp"

#include <dds/dds.h>
#include <fmt/format.h>

#include <kestrel/error.hpp>
#include <thread>

#include "cyclone.hpp"
#include "kestrel/dds/cdr_padding.hpp"
#include "raw_cdr_type.hpp"

namespace kestrel::dds {
namespace {

void set_user_data(dds_qos_t* qos, const WriterMetadata& metadata) {
  const std::string text = encode_metadata(metadata);
  dds_qset_userdata(qos, text.data(), text.size());
}

}  // namespace

std::string encode_metadata(const WriterMetadata& metadata) {
  std::string out;
  for (const auto& [key, value] : metadata) {
    if (key.find_first_of("=;") != std::string::npos || value.find(';') != std::string::npos)
      throw Error(fmt::format("metadata '{}={}' must not hold ';' (nor '=' in its key)", key, value));
    out += key + "=" + value + ";";
  }
  return out;
}

WriterMetadata decode_metadata(std::string_view text) {
  WriterMetadata out;
  std::size_t pos = 0;
  while (pos < text.size()) {
    auto end = text.find(';', pos);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view entry = text.substr(pos, end - pos);
    if (const auto eq = entry.find('='); eq != std::string_view::npos)
      out[std::string(entry.substr(0, eq))] = std::string(entry.substr(eq + 1));
    pos = end + 1;
  }
  return out;
}

Writer::Writer(const Participant& participant, const std::string& dds_topic, const std::string& dds_type,
               const Qos& qos, const WriterMetadata& metadata)
    : topic_(dds_topic), metadata_(metadata) {
  topic_entity_ = detail::create_raw_topic(participant.entity(), dds_topic, dds_type);
  auto q = detail::to_cyclone(qos);
  set_user_data(q.get(), metadata);
  writer_ = dds_create_writer(participant.entity(), topic_entity_, q.get(), nullptr);
  if (writer_ < 0) {
    dds_delete(topic_entity_);
    detail::check(writer_, fmt::format("creating a DDS writer of '{}' ({})", dds_topic, to_string(qos)));
  }
}

Writer::~Writer() {
  dds_delete(writer_);
  dds_delete(topic_entity_);
}

void Writer::write(std::span<const std::uint8_t> cdr) {
  if (cdr.size() < 4)
    throw Error(fmt::format("writing '{}': {} bytes hold no CDR encapsulation header", topic_, cdr.size()));
  // DDS carries whole 4-byte words (cdr_padding.hpp).
  if (cdr.size() % 4 == 0) {
    const detail::RawSample sample{cdr.data(), cdr.size()};
    detail::check(dds_write(writer_, &sample), fmt::format("writing '{}'", topic_));
    return;
  }
  padded_ = pad_cdr(cdr);
  const detail::RawSample sample{padded_.data(), padded_.size()};
  detail::check(dds_write(writer_, &sample), fmt::format("writing '{}'", topic_));
}

void Writer::set_metadata(const WriterMetadata& metadata) {
  if (metadata == metadata_) return;
  detail::QosPtr q(dds_create_qos());
  set_user_data(q.get(), metadata);
  detail::check(dds_set_qos(writer_, q.get()), fmt::format("announcing the metadata of '{}'", topic_));
  metadata_ = metadata;
}

std::size_t Writer::matched_readers() const {
  dds_publication_matched_status_t status{};
  detail::check(dds_get_publication_matched_status(writer_, &status), "reading a writer's matches");
  return status.current_count;
}

bool Writer::wait_for_readers(std::size_t count, std::chrono::milliseconds timeout) const {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (matched_readers() < count) {
    if (std::chrono::steady_clock::now() >= deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return true;
}

}  // namespace kestrel::dds
