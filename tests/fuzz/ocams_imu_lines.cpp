// Fuzz target: the IMU's line parser. Any bytes, as one line, must parse to a sample or a reply,
// or be refused with an ImuLineError; never a crash, and no sample with a non-finite value.
#include <cmath>
#include <cstdint>
#include <string_view>

#include "imu_protocol.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view line(reinterpret_cast<const char*>(data), size);
  try {
    const auto parsed = kestrel::ocams::parse_imu_line(line);
    const auto& s = parsed.sample;
    if (!s.acceleration_m_s2.allFinite() || !s.angular_rate_radps.allFinite() || !s.magnetic_field_t.allFinite())
      __builtin_trap();
    if (s.orientation && !s.orientation->coeffs().allFinite()) __builtin_trap();
  } catch (const kestrel::ocams::ImuLineError&) {
    // a corrupt line: counted by the driver
  }
  return 0;
}
