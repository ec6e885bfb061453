// Fuzz target: the camera_info YAML loader and the rectifier built from what it reads. Any text
// must load or give a kestrel::Error with where and what; a pair that loads must build a rectifier
// or be refused, never crash (the text is used as both the left and, shifted, the right file).
#include "kestrel/stereo_calibration/camera_info.hpp"

#include <cstdint>
#include <kestrel/error.hpp>
#include <string>

#include "kestrel/stereo_calibration/stereo_rectifier.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const auto left = kestrel::calibration::parse_camera_info(text, "fuzz.yaml");
    auto right = left;
    right.p[3] = -right.p[0] * 0.12;
    // Building maps allocates per pixel: keep the sizes small enough for the fuzzer's memory.
    if (left.width <= 2048 && left.height <= 2048) kestrel::calibration::StereoRectifier(left, right);
    kestrel::calibration::parse_camera_info(kestrel::calibration::to_yaml(left), "again.yaml");
  } catch (const kestrel::Error&) {
    // a bad file, or not one rectified pair: the message says which
  }
  return 0;
}
