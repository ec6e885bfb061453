// Fuzz target: the CDR decoders of a recording's messages. Any bytes, read as any kestrel type's
// ROS 2 input or as any defined schema by the generic decoder (`kestrel mcap cat`), must decode
// or give a kestrel::Error; never a crash, a read out of bounds or an allocation the bytes do not
// hold.
#include <cstdint>
#include <cstdlib>

#include "kestrel/ros2/cdr_json.hpp"
#include "kestrel/ros2/definitions.hpp"
#include "kestrel/ros2_messages/message_mapping.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::span<const std::uint8_t> bytes(data + 1, size - 1);
  static const auto types = kestrel::ros2::encodable_types();
  static const auto schemas = kestrel::ros2::defined_types();
  const std::uint8_t pick = data[0];
  try {
    if (pick & 0x80) {
      const std::string& name = schemas[pick % schemas.size()];
      const kestrel::ros2::MessageSchema schema(name, kestrel::ros2::schema_text(name));
      kestrel::ros2::cdr_to_json(schema, bytes);
    } else {
      auto decoder = kestrel::ros2::make_decoder(types[pick % types.size()]);
      const auto inputs = decoder->inputs();
      for (std::size_t i = 0; i < inputs.size(); ++i) decoder->feed(i, bytes, 0, {{"kestrel.pixels_per_point", "1"}});
    }
  } catch (const kestrel::Error&) {
    // bytes that are not that type: the message says what
  }
  return 0;
}
