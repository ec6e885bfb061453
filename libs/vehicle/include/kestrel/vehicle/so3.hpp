#pragma once
// The two maps between 3-vectors and skew-symmetric matrices that rotation errors are written in
// (Lee, Leok & McClamroch 2010): hat(v) * u = v x u, and vee inverts hat; and the attitude a
// multirotor needs to push along a thrust vector with a given heading, which every position
// controller (the Lee controller, the simulated autopilot's) ends in.
#include <Eigen/Core>
#include <cmath>

namespace kestrel::vehicle {

inline Eigen::Matrix3d hat(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return m;
}

inline Eigen::Vector3d vee(const Eigen::Matrix3d& m) { return {m(2, 1), m(0, 2), m(1, 0)}; }

/// The body-to-world rotation whose body z points along `thrust` and whose body x is as close to
/// the heading `yaw` (world z up) as that allows: b2 = b3 x heading, b1 = b2 x b3.
inline Eigen::Matrix3d attitude_along(const Eigen::Vector3d& thrust, double yaw) {
  const Eigen::Vector3d b3 = thrust.normalized();
  const Eigen::Vector3d heading(std::cos(yaw), std::sin(yaw), 0.0);
  Eigen::Vector3d b2 = b3.cross(heading);
  if (b2.norm() < 1e-9) b2 = b3.cross(Eigen::Vector3d::UnitX());  // thrust along the heading: any b2
  b2.normalize();
  Eigen::Matrix3d r;
  r.col(0) = b2.cross(b3);
  r.col(1) = b2;
  r.col(2) = b3;
  return r;
}

}  // namespace kestrel::vehicle
