#include "vehicle_state_conversion.hpp"

#include <cmath>
#include <kestrel/geometry/ned_enu.hpp>

namespace kestrel::mavlink {

namespace {

std::optional<Eigen::Quaterniond> rotation(double w, double x, double y, double z) {
  const Eigen::Quaterniond q(w, x, y, z);
  const double n = q.norm();
  if (!std::isfinite(n) || std::abs(n - 1.0) > 0.01) return std::nullopt;
  return q.normalized();
}

}  // namespace

msg::VehicleState vehicle_state(const LocalPositionNed& p, const AttitudeQuaternion& a) {
  msg::VehicleState s;
  s.position = geometry::ned_to_enu({p.x, p.y, p.z});
  s.velocity = geometry::ned_to_enu({p.vx, p.vy, p.vz});
  const auto q = rotation(a.q1, a.q2, a.q3, a.q4);
  s.orientation = geometry::ned_frd_to_enu_flu(q.value_or(Eigen::Quaterniond::Identity()));
  s.angular_velocity = geometry::frd_to_flu({a.rollspeed, a.pitchspeed, a.yawspeed});
  return s;
}

std::optional<msg::VehicleState> vehicle_state(const Odometry& o) {
  if (o.frame_id != mav::frame_local_ned) return std::nullopt;
  if (o.child_frame_id != mav::frame_body_frd && o.child_frame_id != mav::frame_local_ned) return std::nullopt;
  const auto q_ned_frd = rotation(o.q[0], o.q[1], o.q[2], o.q[3]);
  if (!q_ned_frd) return std::nullopt;
  msg::VehicleState s;
  s.position = geometry::ned_to_enu({o.x, o.y, o.z});
  const Eigen::Vector3d v(o.vx, o.vy, o.vz);
  s.velocity = geometry::ned_to_enu(o.child_frame_id == mav::frame_body_frd ? Eigen::Vector3d(*q_ned_frd * v) : v);
  s.orientation = geometry::ned_frd_to_enu_flu(*q_ned_frd);
  s.angular_velocity = geometry::frd_to_flu({o.rollspeed, o.pitchspeed, o.yawspeed});
  return s;
}

}  // namespace kestrel::mavlink
