#pragma once
// Where a hunter that has lost its target looks for it. Backing off from where the target was
// last seen finds one that slipped out above, below or to the side; one that passed behind the
// hunter, or fled out of range, is not found there. After a while the hunter turns on the spot,
// to the side the target went: its last estimate, flown on at constant velocity since.
#include <Eigen/Core>

namespace kestrel::aim {

/// +1 to turn counter-clockwise (seen from above), -1 clockwise: the side of the hunter's heading
/// `heading_rad` on which `expected_target` (world) lies, from `hunter` (world). Straight ahead
/// or behind, counter-clockwise.
double search_side(double heading_rad, const Eigen::Vector3d& hunter, const Eigen::Vector3d& expected_target);

/// The target's last estimate (position and velocity), flown on for `elapsed_s`.
Eigen::Vector3d expected_position(const Eigen::Vector3d& last_position, const Eigen::Vector3d& last_velocity,
                                  double elapsed_s);

}  // namespace kestrel::aim
