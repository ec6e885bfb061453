#include "kestrel/dds/participant.hpp"

#include <dds/dds.h>
#include <fmt/format.h>

#include <kestrel/error.hpp>

#include "cyclone.hpp"

namespace kestrel::dds {

Participant::Participant(std::uint32_t domain_id) : domain_id_(domain_id) {
  if (domain_id > 232) throw Error(fmt::format("DDS domain {} is out of range (0 to 232)", domain_id));
  entity_ = detail::check(dds_create_participant(domain_id, nullptr, nullptr),
                          fmt::format("joining DDS domain {} (check CYCLONEDDS_URI)", domain_id));
  dds_guid_t guid;
  if (dds_get_guid(entity_, &guid) == DDS_RETCODE_OK) guid_ = detail::hex(guid.v, 12);
}

Participant::~Participant() { dds_delete(entity_); }

}  // namespace kestrel::dds
