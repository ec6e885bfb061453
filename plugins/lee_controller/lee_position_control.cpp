#include "lee_position_control.hpp"

#include <algorithm>
#include <cmath>
#include <kestrel/vehicle/so3.hpp>
#include <kestrel/vehicle/thrust_limit.hpp>

namespace kestrel::control {

LeePositionControl::LeePositionControl(vehicle::Multirotor vehicle, LeeGains gains, double gravity, double max_tilt_rad,
                                       vehicle::RotorMixer::Priority mixer)
    : vehicle_(std::move(vehicle)),
      gains_(std::move(gains)),
      gravity_(gravity),
      max_tilt_rad_(max_tilt_rad),
      mixer_(vehicle_, mixer) {}

Eigen::Vector3d LeePositionControl::attitude_error(const Eigen::Matrix3d& desired, const Eigen::Matrix3d& actual) {
  return 0.5 * vehicle::vee(desired.transpose() * actual - actual.transpose() * desired);
}

Eigen::VectorXd LeePositionControl::allocate(const Eigen::Vector3d& torque, double thrust, bool* saturated) const {
  vehicle::RotorMixer::Mix mix = mixer_.mix(torque, thrust);
  if (saturated) *saturated = mix.saturated;
  return std::move(mix.speeds);
}

LeeCommand LeePositionControl::compute(const msg::TrajectorySetpoint& sp, const msg::VehicleState& state) const {
  LeeCommand out;
  const double m = vehicle_.mass_kg;
  const Eigen::Vector3d e3 = Eigen::Vector3d::UnitZ();
  // Translational law: the force that drives the position and velocity errors down, holds the
  // vehicle against gravity and feeds the desired acceleration forward.
  const Eigen::Vector3d ex = state.position - sp.position;
  const Eigen::Vector3d ev = state.velocity - sp.velocity;
  Eigen::Vector3d force =
      -gains_.position.cwiseProduct(ex) - gains_.velocity.cwiseProduct(ev) + m * gravity_ * e3 + m * sp.acceleration;
  // A multirotor cannot pull down, and must not tilt past max_tilt: keep some upward force and
  // shorten the horizontal part.
  const vehicle::LimitedThrust limit = vehicle::limit_thrust(force, 0.1 * m * gravity_, max_tilt_rad_);
  const bool limited = limit.raised || limit.tilted;
  force = limit.thrust;
  out.force_world = force;

  const Eigen::Matrix3d r = state.orientation.toRotationMatrix();
  out.attitude = vehicle::attitude_along(force, sp.yaw);
  out.thrust_n = force.dot(r.col(2));  // what the current body z can deliver of it

  // Rotational law: attitude and body-rate errors, with the gyroscopic term cancelled.
  out.body_rates = Eigen::Vector3d(0.0, 0.0, sp.yaw_rate);
  out.attitude_error = attitude_error(out.attitude, r);
  out.rate_error = state.angular_velocity - r.transpose() * out.attitude * out.body_rates;
  const Eigen::Vector3d momentum = vehicle_.inertia_kg_m2.cwiseProduct(state.angular_velocity);
  out.torque_nm = -gains_.attitude.cwiseProduct(out.attitude_error) - gains_.angular_rate.cwiseProduct(out.rate_error) +
                  state.angular_velocity.cross(momentum);

  bool clipped = false;
  out.rotor_speeds = allocate(out.torque_nm, out.thrust_n, &clipped);
  out.saturated = limited || clipped;
  return out;
}

}  // namespace kestrel::control
