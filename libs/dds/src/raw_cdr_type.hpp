#pragma once
// A Cyclone DDS type whose samples are already serialized: the CDR bytes of a ROS 2 message,
// encapsulation header first, exactly as the recording writes them. Cyclone carries them without
// knowing the type's fields, as rmw_cyclonedds_cpp does for ROS 2's own messages, so that one
// serializer (kestrel::ros2_messages) feeds MCAP files, the live view and DDS alike.
#include <dds/dds.h>
#include <dds/ddsi/ddsi_keyhash.h>
#include <dds/ddsi/ddsi_serdata.h>
#include <dds/ddsi/ddsi_sertype.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace kestrel::dds::detail {

/// What dds_write() takes for this type: a view of the bytes to send.
struct RawSample {
  const std::uint8_t* data = nullptr;
  std::size_t size = 0;
};

/// A received or written sample: the bytes, kept as they came.
struct RawSerdata : ddsi_serdata {
  std::vector<std::uint8_t> bytes;
};

/// A new sertype named `dds_type_name` (keyless, XCDR1). Ownership passes to Cyclone once
/// dds_create_topic_sertype() succeeds; before that, free it with ddsi_sertype_unref().
ddsi_sertype* make_raw_cdr_sertype(const std::string& dds_type_name);

}  // namespace kestrel::dds::detail
