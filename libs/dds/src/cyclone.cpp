#include "cyclone.hpp"

#include <fmt/format.h>

#include <kestrel/error.hpp>

#include "raw_cdr_type.hpp"

namespace kestrel::dds::detail {

std::int32_t check(std::int32_t rc, const std::string& what) {
  if (rc < 0) throw Error(fmt::format("{}: {}", what, dds_strretcode(rc)));
  return rc;
}

QosPtr to_cyclone(const Qos& qos) {
  QosPtr q(dds_create_qos());
  dds_qset_reliability(
      q.get(), qos.reliability == Reliability::reliable ? DDS_RELIABILITY_RELIABLE : DDS_RELIABILITY_BEST_EFFORT,
      DDS_MSECS(100));
  dds_qset_history(q.get(), DDS_HISTORY_KEEP_LAST, qos.depth);
  dds_qset_durability(
      q.get(), qos.durability == Durability::volatile_ ? DDS_DURABILITY_VOLATILE : DDS_DURABILITY_TRANSIENT_LOCAL);
  // Cyclone keeps a late reader's history by the durability service's policy (keep last 1 unless
  // told): the same depth, as ROS 2's transient local promises.
  if (qos.durability == Durability::transient_local)
    dds_qset_durability_service(q.get(), 0, DDS_HISTORY_KEEP_LAST, qos.depth, DDS_LENGTH_UNLIMITED,
                                DDS_LENGTH_UNLIMITED, DDS_LENGTH_UNLIMITED);
  const dds_data_representation_id_t xcdr1 = DDS_DATA_REPRESENTATION_XCDR1;
  dds_qset_data_representation(q.get(), 1, &xcdr1);
  return q;
}

Qos from_cyclone(const dds_qos_t* qos) {
  Qos out;
  dds_reliability_kind_t reliability;
  dds_duration_t blocking;
  if (dds_qget_reliability(qos, &reliability, &blocking))
    out.reliability = reliability == DDS_RELIABILITY_RELIABLE ? Reliability::reliable : Reliability::best_effort;
  dds_history_kind_t history;
  std::int32_t depth = 0;
  if (dds_qget_history(qos, &history, &depth)) out.depth = history == DDS_HISTORY_KEEP_LAST ? depth : 0;
  dds_durability_kind_t durability;
  if (dds_qget_durability(qos, &durability))
    out.durability = durability == DDS_DURABILITY_VOLATILE ? Durability::volatile_ : Durability::transient_local;
  return out;
}

std::string hex(const unsigned char* bytes, std::size_t size) {
  std::string out;
  for (std::size_t i = 0; i < size; ++i) out += fmt::format("{:02x}", bytes[i]);
  return out;
}

std::int32_t create_raw_topic(std::int32_t participant, const std::string& dds_topic, const std::string& dds_type) {
  ddsi_sertype* sertype = make_raw_cdr_sertype(dds_type);
  ddsi_sertype* used = sertype;
  const dds_entity_t topic = dds_create_topic_sertype(participant, dds_topic.c_str(), &used, nullptr, nullptr, nullptr);
  if (topic < 0) {
    ddsi_sertype_unref(sertype);
    check(topic, fmt::format("creating DDS topic '{}' of type '{}'", dds_topic, dds_type));
  }
  return topic;
}

}  // namespace kestrel::dds::detail
