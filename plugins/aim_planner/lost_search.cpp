#include "lost_search.hpp"

#include <cmath>

namespace kestrel::aim {

double search_side(double heading_rad, const Eigen::Vector3d& hunter, const Eigen::Vector3d& expected_target) {
  const Eigen::Vector2d to_target = (expected_target - hunter).head<2>();
  // The z of heading x to_target: positive where the target is to the left.
  const double across = std::cos(heading_rad) * to_target.y() - std::sin(heading_rad) * to_target.x();
  return across < 0.0 ? -1.0 : 1.0;
}

Eigen::Vector3d expected_position(const Eigen::Vector3d& last_position, const Eigen::Vector3d& last_velocity,
                                  double elapsed_s) {
  return last_position + last_velocity * elapsed_s;
}

}  // namespace kestrel::aim
