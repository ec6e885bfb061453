#pragma once
// What this library's sources share about Cyclone: its return codes as kestrel errors, and
// kestrel's QoS as Cyclone's.
#include <dds/dds.h>

#include <memory>
#include <string>

#include "kestrel/dds/qos.hpp"

namespace kestrel::dds::detail {

/// Throws kestrel::Error "WHAT: Cyclone's reason" when `rc` is negative; returns it otherwise.
std::int32_t check(std::int32_t rc, const std::string& what);

struct QosDeleter {
  void operator()(dds_qos_t* q) const { dds_delete_qos(q); }
};
using QosPtr = std::unique_ptr<dds_qos_t, QosDeleter>;

/// `qos` as Cyclone's, with XCDR1 (what ROS 2 Humble writes) as the data representation.
QosPtr to_cyclone(const Qos& qos);
/// The three policies back from an endpoint's QoS (discovery).
Qos from_cyclone(const dds_qos_t* qos);

/// A GUID or GUID prefix as hex.
std::string hex(const unsigned char* bytes, std::size_t size);

/// A topic of the raw CDR type named `dds_type` on the participant.
std::int32_t create_raw_topic(std::int32_t participant, const std::string& dds_topic, const std::string& dds_type);

}  // namespace kestrel::dds::detail
