#pragma once
// The two maps between 3-vectors and skew-symmetric matrices that rotation errors are written in
// (Lee, Leok & McClamroch 2010): hat(v) * u = v x u, and vee inverts hat.
#include <Eigen/Core>

namespace kestrel::vehicle {

inline Eigen::Matrix3d hat(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return m;
}

inline Eigen::Vector3d vee(const Eigen::Matrix3d& m) { return {m(2, 1), m(0, 2), m(1, 0)}; }

}  // namespace kestrel::vehicle
