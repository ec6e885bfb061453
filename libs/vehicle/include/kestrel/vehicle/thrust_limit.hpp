#pragma once
// The thrust a multirotor can point: its rotors push only up its body z, so the thrust never
// points down, and the airframe tilts no further than its limit. Every position controller (the
// Lee controller, the simulated autopilot's) limits its thrust so, and the aim plans for the
// attitude that results.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>

namespace kestrel::vehicle {

struct LimitedThrust {
  Eigen::Vector3d thrust = Eigen::Vector3d::Zero();
  bool raised = false;  ///< its upward part was raised to the minimum
  bool tilted = false;  ///< its horizontal part was shortened to the tilt limit
};

/// `thrust` (world, z up) with at least `min_up` upward and tilted at most `max_tilt_rad` from
/// vertical. The vertical part keeps priority: the horizontal part is shortened, not the height lost.
inline LimitedThrust limit_thrust(Eigen::Vector3d thrust, double min_up, double max_tilt_rad) {
  LimitedThrust out;
  if (thrust.z() < min_up) {
    thrust.z() = min_up;
    out.raised = true;
  }
  const double horizontal = thrust.head<2>().norm(), max_horizontal = thrust.z() * std::tan(max_tilt_rad);
  if (horizontal > max_horizontal) {
    thrust.head<2>() *= max_horizontal / horizontal;
    out.tilted = true;
  }
  out.thrust = thrust;
  return out;
}

/// What a multirotor flies of `acceleration` (world, z up) within `max_tilt_rad`: its thrust per
/// unit mass (the acceleration plus gravity) limited as above, with a tenth of gravity upward at least.
inline Eigen::Vector3d tilt_limited_acceleration(const Eigen::Vector3d& acceleration, double max_tilt_rad,
                                                 double gravity_m_s2) {
  const Eigen::Vector3d up(0.0, 0.0, gravity_m_s2);
  return limit_thrust(acceleration + up, 0.1 * gravity_m_s2, max_tilt_rad).thrust - up;
}

}  // namespace kestrel::vehicle
