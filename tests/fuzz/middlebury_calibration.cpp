// Fuzz target: Middlebury calib.txt files. Any text must load or give a kestrel::Error with where
// and what; a calibration that loads must give a camera_info pair the rectifier takes or refuses.
#include "kestrel/stereo_calibration/middlebury_calibration.hpp"

#include <cstdint>
#include <kestrel/error.hpp>
#include <string>

#include "kestrel/stereo_calibration/stereo_rectifier.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const auto calibration = kestrel::calibration::parse_middlebury_calibration(text, "calib.txt");
    const auto [left, right] = calibration.camera_infos();
    // Building maps allocates per pixel: keep the sizes small enough for the fuzzer's memory.
    if (left.width <= 2048 && left.height <= 2048) kestrel::calibration::StereoRectifier(left, right);
  } catch (const kestrel::Error&) {
    // a bad file, or not one rectified pair: the message says which
  }
  return 0;
}
