#pragma once
// The oCamS-1CGN-U's frame as it comes off USB, and its inverse. The camera announces a YUYV
// stream of the size of one eye, but each 16-bit word carries two 8-bit Bayer GRBG samples: the
// low byte (even offsets) is the right image's, the high byte (odd offsets) the left's, as
// WithRobot's driver splits them. The first 4 bytes hold the device's clock, a little-endian
// uint32 in milliseconds, written over the first two pixels of each eye.
#include <cstdint>
#include <opencv2/core.hpp>
#include <span>
#include <vector>

namespace kestrel::ocams {

/// One eye each: 8-bit GRBG mosaics of the announced size.
struct BayerPair {
  cv::Mat left, right;
  std::uint32_t device_ms = 0;  ///< the device's clock at capture
};

/// Bytes of one raw frame: two per pixel.
constexpr std::size_t raw_frame_bytes(int width, int height) {
  return 2u * static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
}

/// The device clock a raw frame carries in its first 4 bytes; 0 for fewer bytes.
std::uint32_t device_clock_ms(std::span<const std::uint8_t> raw);

/// Splits a raw frame into its two mosaics and reads its clock. The pixels the clock overwrote
/// are given their Bayer neighbours' values two rows down, so that no stage sees the stamp as
/// image. Throws kestrel::Error when `raw` is not width x height x 2 bytes or the size is not
/// even in both directions (a Bayer mosaic's period).
BayerPair unpack(std::span<const std::uint8_t> raw, int width, int height);

/// The inverse of unpack(): packs two GRBG mosaics and a clock into a raw frame, as the camera
/// sends it (used by tests, the fake device and to make raw recordings from rendered images).
std::vector<std::uint8_t> pack(const cv::Mat& left_bayer, const cv::Mat& right_bayer, std::uint32_t device_ms);

/// Samples a BGR (or grey) image into a GRBG mosaic, as the sensor's colour filter does.
cv::Mat mosaic_grbg(const cv::Mat& image);

}  // namespace kestrel::ocams
