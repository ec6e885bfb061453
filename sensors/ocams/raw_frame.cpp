#include "raw_frame.hpp"

#include <cstring>
#include <kestrel/error.hpp>

namespace kestrel::ocams {

std::uint32_t device_clock_ms(std::span<const std::uint8_t> raw) {
  if (raw.size() < 4) return 0;
  return static_cast<std::uint32_t>(raw[0]) | static_cast<std::uint32_t>(raw[1]) << 8 |
         static_cast<std::uint32_t>(raw[2]) << 16 | static_cast<std::uint32_t>(raw[3]) << 24;
}

BayerPair unpack(std::span<const std::uint8_t> raw, int width, int height) {
  if (width < 4 || height < 4 || width % 2 != 0 || height % 2 != 0)
    throw Error("an oCamS frame of " + std::to_string(width) + "x" + std::to_string(height) +
                ": a Bayer pair needs an even size of at least 4x4");
  if (raw.size() != raw_frame_bytes(width, height))
    throw Error("an oCamS frame of " + std::to_string(raw.size()) + " bytes for " + std::to_string(width) + "x" +
                std::to_string(height) + " (" + std::to_string(raw_frame_bytes(width, height)) + " expected)");
  BayerPair pair;
  pair.device_ms = device_clock_ms(raw);
  // A header over const bytes: split() only reads it.
  const cv::Mat words(height, width, CV_8UC2, const_cast<std::uint8_t*>(raw.data()));
  cv::Mat planes[2];
  cv::split(words, planes);
  pair.right = planes[0];
  pair.left = planes[1];
  for (cv::Mat* eye : {&pair.left, &pair.right})
    for (int col = 0; col < 2; ++col) eye->at<std::uint8_t>(0, col) = eye->at<std::uint8_t>(2, col);
  return pair;
}

std::vector<std::uint8_t> pack(const cv::Mat& left_bayer, const cv::Mat& right_bayer, std::uint32_t device_ms) {
  if (left_bayer.type() != CV_8UC1 || right_bayer.type() != CV_8UC1 || left_bayer.size() != right_bayer.size())
    throw Error("pack() takes two 8-bit mosaics of one size");
  std::vector<std::uint8_t> raw(raw_frame_bytes(left_bayer.cols, left_bayer.rows));
  cv::Mat words(left_bayer.rows, left_bayer.cols, CV_8UC2, raw.data());
  const cv::Mat planes[2] = {right_bayer, left_bayer};
  cv::merge(planes, 2, words);
  for (int i = 0; i < 4; ++i) raw[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(device_ms >> (8 * i));
  return raw;
}

cv::Mat mosaic_grbg(const cv::Mat& image) {
  if (image.type() == CV_8UC1) return image.clone();
  if (image.type() != CV_8UC3) throw Error("mosaic_grbg() takes an 8-bit grey or BGR image");
  cv::Mat out(image.size(), CV_8UC1);
  for (int r = 0; r < image.rows; ++r) {
    const auto* in = image.ptr<cv::Vec3b>(r);
    auto* o = out.ptr<std::uint8_t>(r);
    for (int c = 0; c < image.cols; ++c) {
      // G R on even rows, B G on odd ones; BGR channels 0 = B, 1 = G, 2 = R.
      const bool even_row = r % 2 == 0, even_col = c % 2 == 0;
      const int channel = even_row == even_col ? 1 : (even_row ? 2 : 0);
      o[c] = in[c][channel];
    }
  }
  return out;
}

}  // namespace kestrel::ocams
