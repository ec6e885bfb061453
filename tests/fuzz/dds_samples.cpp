// Fuzz target: what a DDS peer hands kestrel's subscription. A peer's USER_DATA (the metadata
// its writers announce) and a sample's bytes, padding counted in the encapsulation options, read
// as any kestrel type's ROS 2 input: they must decode or give a kestrel::Error; never a crash, a
// read out of bounds or an allocation the bytes do not hold.
#include <cstdint>
#include <string_view>

#include "kestrel/dds/cdr_padding.hpp"
#include "kestrel/dds/writer.hpp"
#include "kestrel/error.hpp"
#include "kestrel/ros2_messages/message_mapping.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  // data[0]: the type; data[1]: how many of the next bytes are USER_DATA; the rest: the sample.
  static const auto types = kestrel::ros2::encodable_types();
  const std::size_t user_data = std::min<std::size_t>(data[1], size - 2);
  const auto metadata =
      kestrel::dds::decode_metadata(std::string_view(reinterpret_cast<const char*>(data + 2), user_data));
  std::vector<std::uint8_t> sample(data + 2 + user_data, data + size);
  kestrel::dds::strip_cdr_padding(sample);
  try {
    auto decoder = kestrel::ros2::make_decoder(types[data[0] % types.size()]);
    const auto inputs = decoder->inputs();
    for (std::size_t i = 0; i < inputs.size(); ++i) decoder->feed(i, sample, 0, metadata);
  } catch (const kestrel::Error&) {
    // bytes that are not that type: the message says what
  }
  return 0;
}
