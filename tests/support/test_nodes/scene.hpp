#pragma once
// The known scene of the `scene_source` test node, shared with the tests that check what nodes
// made of it.
#include <Eigen/Core>
#include <cmath>
#include <cstdint>

namespace kestrel::test {

/// Where the intruder is in frame k (camera frame, metres): a curve with a different value in
/// every frame, with digits a rounding writer would lose.
inline Eigen::Vector3d scene_position(std::int64_t k) {
  const double t = static_cast<double>(k);
  return {1.25 * std::sin(0.3 * t) + 0.001 * t, 0.5 * std::cos(0.2 * t) - 0.123456789, 5.0 + 0.0625 * t};
}

/// Frame k has no detection when miss_every > 0 and k % miss_every == miss_every - 1.
inline bool scene_detects(std::int64_t k, std::int64_t miss_every) {
  return miss_every == 0 || k % miss_every != miss_every - 1;
}

}  // namespace kestrel::test
