#pragma once
// DDS carries a serialized sample as whole 4-byte words: a writer pads the CDR bytes and says how
// many bytes it added in the low two bits of the encapsulation options (XTypes 1.3, 7.6.3.1.2),
// as ROS 2's RMWs do; a reader takes them off again, so that what it hands on is the message as an
// MCAP file holds it.
#include <cstdint>
#include <span>
#include <vector>

namespace kestrel::dds {

/// `cdr` (encapsulation header first) padded to a multiple of 4 bytes, the padding counted in the
/// options. Unchanged when it is one already.
std::vector<std::uint8_t> pad_cdr(std::span<const std::uint8_t> cdr);

/// Takes off the padding the options count, when the sample is long enough to hold it; the options
/// then count none.
void strip_cdr_padding(std::vector<std::uint8_t>& cdr);

}  // namespace kestrel::dds
