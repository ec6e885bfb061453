#pragma once
// The two conventions a hunter's software meets, converted in one place. kestrel works in ENU
// (x east, y north, z up) for the world and FLU (x forward, y left, z up) for the body, as ROS
// does (REP 103). PX4, ArduPilot and MAVLink use NED (x north, y east, z down) and FRD (x forward,
// y right, z down). Both pairs are proper rotations of each other, so every conversion is its
// own inverse for vectors, and orientations conjugate by them.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

namespace kestrel::geometry {

/// A world-frame vector (position, velocity, acceleration) from ENU to NED: swap x and y, negate z.
inline Eigen::Vector3d enu_to_ned(const Eigen::Vector3d& v) { return {v.y(), v.x(), -v.z()}; }
/// A world-frame vector from NED to ENU (the same swap).
inline Eigen::Vector3d ned_to_enu(const Eigen::Vector3d& v) { return {v.y(), v.x(), -v.z()}; }

/// A body-frame vector (body rates, forces) from FLU to FRD: negate y and z.
inline Eigen::Vector3d flu_to_frd(const Eigen::Vector3d& v) { return {v.x(), -v.y(), -v.z()}; }
/// A body-frame vector from FRD to FLU.
inline Eigen::Vector3d frd_to_flu(const Eigen::Vector3d& v) { return {v.x(), -v.y(), -v.z()}; }

/// The rotation that takes ENU coordinates to NED ones (a half turn about the NE diagonal).
inline Eigen::Quaterniond ned_from_enu() {
  return Eigen::Quaterniond(0.0, std::numbers::sqrt2 / 2.0, std::numbers::sqrt2 / 2.0, 0.0);
}
/// The rotation that takes FRD coordinates to FLU ones (a half turn about x).
inline Eigen::Quaterniond flu_from_frd() { return Eigen::Quaterniond(0.0, 1.0, 0.0, 0.0); }

/// An attitude that rotates FLU body vectors into ENU, as one that rotates FRD body vectors into
/// NED (MAVLink's ATTITUDE_QUATERNION, SET_ATTITUDE_TARGET, ODOMETRY).
inline Eigen::Quaterniond enu_flu_to_ned_frd(const Eigen::Quaterniond& q_enu_flu) {
  return (ned_from_enu() * q_enu_flu * flu_from_frd()).normalized();
}
/// An attitude that rotates FRD body vectors into NED, as one that rotates FLU into ENU.
inline Eigen::Quaterniond ned_frd_to_enu_flu(const Eigen::Quaterniond& q_ned_frd) {
  return (ned_from_enu().conjugate() * q_ned_frd * flu_from_frd().conjugate()).normalized();
}

/// An angle wrapped into (-pi, pi].
inline double wrap_angle(double a) {
  a = std::remainder(a, 2.0 * std::numbers::pi);
  return a <= -std::numbers::pi ? a + 2.0 * std::numbers::pi : a;
}
/// A heading about ENU's z (0 = east, counter-clockwise) as one about NED's z (0 = north, clockwise).
inline double yaw_enu_to_ned(double yaw_enu) { return wrap_angle(std::numbers::pi / 2.0 - yaw_enu); }
/// A heading about NED's z as one about ENU's z.
inline double yaw_ned_to_enu(double yaw_ned) { return wrap_angle(std::numbers::pi / 2.0 - yaw_ned); }

}  // namespace kestrel::geometry
