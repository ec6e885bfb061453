#include "sensor_noise.hpp"

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace kestrel::sim {

cv::Mat SensorNoise::apply(const cv::Mat& bgr, std::uint64_t seed) {
  cv::Mat image;
  if (colour_)
    image = bgr;
  else
    cv::cvtColor(bgr, image, cv::COLOR_BGR2GRAY);
  if (sigma_ <= 0) return image;
  cv::RNG generator(seed);
  noise_.create(image.size(), CV_32FC(image.channels()));
  generator.fill(noise_, cv::RNG::NORMAL, 0.0, sigma_);
  image.convertTo(sum_, noise_.type());
  sum_ += noise_;
  cv::Mat noisy;
  sum_.convertTo(noisy, image.type());
  return noisy;
}

}  // namespace kestrel::sim
