#pragma once
// A rendered image as the camera delivers it: 8-bit grey (or BGR), plus Gaussian sensor noise,
// rounded and saturated as a sensor's converter does. The noise comes from OpenCV's generator
// (multiply-with-carry, Ziggurat normals) seeded per image: a fifth of the time of
// std::normal_distribution, and as reproducible.
#include <cstdint>
#include <opencv2/core/mat.hpp>

namespace kestrel::sim {

class SensorNoise {
 public:
  SensorNoise(double sigma, bool colour) : sigma_(sigma), colour_(colour) {}
  /// `bgr` as delivered, with noise drawn from `seed`. A new image each call.
  cv::Mat apply(const cv::Mat& bgr, std::uint64_t seed);

 private:
  double sigma_;  // grey levels
  bool colour_;
  cv::Mat noise_, sum_;  // working buffers, kept from image to image
};

}  // namespace kestrel::sim
