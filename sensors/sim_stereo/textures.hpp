#pragma once
// Procedural textures for the simulated world. Stereo matching needs texture at the scale the
// camera sees, so every surface gets seeded multi-scale noise rather than a flat colour.
#include <cstdint>
#include <opencv2/core/mat.hpp>

namespace kestrel::sim {

struct TextureStyle {
  cv::Vec3b dark;            ///< BGR
  cv::Vec3b light;           ///< BGR
  double fine_weight = 0.5;  ///< share of pixel-scale noise against blotches
  int blotch_px = 8;         ///< blur radius of the coarse layer, pixels
};

/// A size x size BGR texture mixing `dark` and `light` by seeded noise at two scales.
cv::Mat make_texture(int size, const TextureStyle& style, std::uint64_t seed);

TextureStyle grass_style();
TextureStyle drone_style();
TextureStyle bark_style();
TextureStyle foliage_style();
TextureStyle concrete_style();
TextureStyle sky_style();

}  // namespace kestrel::sim
