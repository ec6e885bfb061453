#include "flight_control.hpp"

#include <algorithm>
#include <cmath>
#include <kestrel/geometry/frames.hpp>
#include <kestrel/vehicle/so3.hpp>
#include <kestrel/vehicle/thrust_limit.hpp>
#include <numbers>

namespace kestrel::sim_autopilot {

namespace {

constexpr double deg = std::numbers::pi / 180.0;

}  // namespace

FlightControl::FlightControl(const vehicle::Multirotor& vehicle, FlightControlGains gains, double gravity,
                             double max_thrust_n)
    : vehicle_(vehicle), gains_(gains), gravity_(gravity), max_thrust_n_(max_thrust_n) {}

void FlightControl::reset() {
  velocity_integral_.setZero();
  rate_integral_.setZero();
  last_velocity_error_.reset();
  last_rate_error_.reset();
}

BodyWrench FlightControl::position(const PositionTarget& target, const vehicle::RigidBodyState& s, double dt) {
  // Velocity setpoint: the feed-forward plus the position error through P, within the limits.
  Eigen::Vector3d velocity_sp = target.velocity.value_or(Eigen::Vector3d::Zero());
  if (target.position) velocity_sp += gains_.position_p.cwiseProduct(*target.position - s.position);
  const double xy = velocity_sp.head<2>().norm();
  if (xy > gains_.max_speed_xy_m_s) velocity_sp.head<2>() *= gains_.max_speed_xy_m_s / xy;
  velocity_sp.z() = std::clamp(velocity_sp.z(), -gains_.max_speed_down_m_s, gains_.max_speed_up_m_s);

  // Acceleration setpoint: velocity PID plus the feed-forward.
  const Eigen::Vector3d error = velocity_sp - s.velocity;
  const Eigen::Vector3d derivative =
      last_velocity_error_ && dt > 0 ? Eigen::Vector3d((error - *last_velocity_error_) / dt) : Eigen::Vector3d::Zero();
  last_velocity_error_ = error;
  Eigen::Vector3d acceleration = gains_.velocity_p.cwiseProduct(error) + velocity_integral_ +
                                 gains_.velocity_d.cwiseProduct(derivative) +
                                 target.acceleration.value_or(Eigen::Vector3d::Zero());

  // Thrust vector, its tilt limited; the vertical part keeps priority.
  const vehicle::LimitedThrust limit =
      vehicle::limit_thrust(vehicle_.mass_kg * (acceleration + Eigen::Vector3d(0.0, 0.0, gravity_)),
                            0.1 * vehicle_.mass_kg * gravity_, gains_.max_tilt_deg * deg);
  const Eigen::Vector3d& thrust = limit.thrust;
  const bool tilt_limited = limit.tilted;
  const bool saturated = thrust.norm() >= max_thrust_n_;
  // Anti-windup: integrate only while the thrust can follow.
  if (!tilt_limited && !saturated) velocity_integral_ += gains_.velocity_i.cwiseProduct(error) * dt;

  const double yaw = target.yaw.value_or(geometry::yaw_of(s.orientation));
  const Eigen::Quaterniond desired(vehicle::attitude_along(thrust, yaw));
  BodyWrench out;
  // Thrust along the body z the vehicle has now: tilted away from the thrust vector, it pushes less.
  out.thrust_n = std::clamp(thrust.dot(s.orientation * Eigen::Vector3d::UnitZ()), 0.0, max_thrust_n_);
  out.torque_nm = torque(rate_setpoint(desired, s), s, dt);
  return out;
}

BodyWrench FlightControl::attitude(const AttitudeCommand& command, const vehicle::RigidBodyState& s, double dt) {
  last_velocity_error_.reset();
  Eigen::Vector3d rate_sp = command.body_rates;
  if (command.orientation) rate_sp += rate_setpoint(*command.orientation, s);
  BodyWrench out;
  out.thrust_n = std::clamp(command.thrust_n, 0.0, max_thrust_n_);
  out.torque_nm = torque(rate_sp, s, dt);
  return out;
}

Eigen::Vector3d FlightControl::rate_setpoint(const Eigen::Quaterniond& desired,
                                             const vehicle::RigidBodyState& s) const {
  Eigen::Quaterniond error = s.orientation.conjugate() * desired;  // body frame
  if (error.w() < 0.0) error.coeffs() = -error.coeffs();           // the short way round
  Eigen::Vector3d rates = 2.0 * gains_.attitude_p.cwiseProduct(error.vec());
  const Eigen::Vector3d limit = gains_.max_rate_deg_s * deg;
  return rates.cwiseMax(-limit).cwiseMin(limit);
}

Eigen::Vector3d FlightControl::torque(const Eigen::Vector3d& rate_sp, const vehicle::RigidBodyState& s, double dt) {
  const Eigen::Vector3d error = rate_sp - s.angular_velocity;
  const Eigen::Vector3d derivative =
      last_rate_error_ && dt > 0 ? Eigen::Vector3d((error - *last_rate_error_) / dt) : Eigen::Vector3d::Zero();
  last_rate_error_ = error;
  rate_integral_ += gains_.rate_i.cwiseProduct(error) * dt;
  const Eigen::Vector3d integral_limit = 0.3 * gains_.rate_p;  // at most 0.3 rad/s of error's worth
  rate_integral_ = rate_integral_.cwiseMax(-integral_limit).cwiseMin(integral_limit);
  const Eigen::Vector3d angular_acceleration =
      gains_.rate_p.cwiseProduct(error) + rate_integral_ + gains_.rate_d.cwiseProduct(derivative);
  const Eigen::Vector3d& j = vehicle_.inertia_kg_m2;
  const Eigen::Vector3d w = s.angular_velocity;
  return j.cwiseProduct(angular_acceleration) + w.cross(j.cwiseProduct(w));
}

}  // namespace kestrel::sim_autopilot
