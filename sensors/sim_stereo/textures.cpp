#include "textures.hpp"

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <random>

namespace kestrel::sim {

cv::Mat make_texture(int size, const TextureStyle& style, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<float> uniform(0.f, 1.f);
  cv::Mat fine(size, size, CV_32F), coarse(size, size, CV_32F);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      fine.at<float>(y, x) = uniform(rng);
      coarse.at<float>(y, x) = uniform(rng);
    }
  const int k = 2 * style.blotch_px + 1;
  cv::GaussianBlur(coarse, coarse, cv::Size(k, k), 0, 0, cv::BORDER_REFLECT);
  cv::normalize(coarse, coarse, 0.f, 1.f, cv::NORM_MINMAX);
  cv::GaussianBlur(fine, fine, cv::Size(3, 3), 0, 0, cv::BORDER_REFLECT);
  cv::normalize(fine, fine, 0.f, 1.f, cv::NORM_MINMAX);
  cv::Mat mix = style.fine_weight * fine + (1.0 - style.fine_weight) * coarse;

  cv::Mat out(size, size, CV_8UC3);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const float f = mix.at<float>(y, x);
      cv::Vec3b& p = out.at<cv::Vec3b>(y, x);
      for (int c = 0; c < 3; ++c)
        p[c] = cv::saturate_cast<uchar>(style.dark[c] + f * (static_cast<float>(style.light[c]) - style.dark[c]));
    }
  return out;
}

TextureStyle grass_style() { return {{20, 60, 35}, {60, 150, 110}, 0.55, 6}; }
TextureStyle drone_style() { return {{25, 25, 25}, {235, 235, 235}, 0.7, 3}; }
TextureStyle bark_style() { return {{20, 35, 55}, {70, 100, 130}, 0.6, 4}; }
TextureStyle foliage_style() { return {{15, 55, 20}, {70, 160, 80}, 0.5, 5}; }
TextureStyle concrete_style() { return {{90, 90, 95}, {200, 200, 205}, 0.6, 6}; }
TextureStyle sky_style() { return {{200, 175, 150}, {250, 245, 240}, 0.25, 10}; }

}  // namespace kestrel::sim
