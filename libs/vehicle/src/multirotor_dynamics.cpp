#include "kestrel/vehicle/multirotor_dynamics.hpp"

#include <algorithm>
#include <cmath>
#include <kestrel/geometry/frames.hpp>

namespace kestrel::vehicle {

MultirotorDynamics::MultirotorDynamics(Multirotor vehicle)
    : vehicle_(std::move(vehicle)),
      wrench_matrix_(vehicle_.wrench_matrix()),
      inertia_(vehicle_.inertia_kg_m2),
      inverse_inertia_(vehicle_.inertia_kg_m2.cwiseInverse()) {}

MultirotorDynamics::Wrench MultirotorDynamics::rotor_wrench(const RigidBodyState& s,
                                                            const Eigen::Vector3d& wind) const {
  const Eigen::VectorXd squared = s.rotor_speeds.cwiseAbs2();
  const Eigen::Vector4d w = wrench_matrix_ * squared;
  Wrench out;
  out.torque = w.head<3>();
  out.force = Eigen::Vector3d(0.0, 0.0, w(3));
  // Rotor drag (RotorS' model): each spinning disc resists the airspeed across it, in proportion
  // to its speed. The airspeed along the rotor axis is left to the thrust model.
  const Eigen::Vector3d air_body = s.orientation.conjugate() * (s.velocity - wind);
  const Eigen::Vector3d across(air_body.x(), air_body.y(), 0.0);
  out.force -= vehicle_.rotor_drag_coefficient * s.rotor_speeds.cwiseAbs().sum() * across;
  return out;
}

MultirotorDynamics::Derivative MultirotorDynamics::derivative(const RigidBodyState& s, const Eigen::VectorXd& commanded,
                                                              const Environment& env) const {
  const Wrench wrench = rotor_wrench(s, env.wind);
  Derivative d;
  d.position = s.velocity;
  d.velocity = s.orientation * wrench.force / vehicle_.mass_kg - Eigen::Vector3d(0.0, 0.0, env.gravity);
  // q' = q * (0, w) / 2, with w in the body frame.
  const Eigen::Quaterniond rate(0.0, s.angular_velocity.x(), s.angular_velocity.y(), s.angular_velocity.z());
  d.orientation = 0.5 * (s.orientation * rate).coeffs();
  // Euler's equation: J w' = tau - w x J w.
  const Eigen::Vector3d momentum = inertia_.cwiseProduct(s.angular_velocity);
  d.angular_velocity = inverse_inertia_.cwiseProduct(wrench.torque - s.angular_velocity.cross(momentum));
  d.rotor_speeds.resize(s.rotor_speeds.size());
  for (Eigen::Index i = 0; i < s.rotor_speeds.size(); ++i) {
    const double target = std::clamp(commanded(i), 0.0, vehicle_.max_rotor_speed_rad_s);
    const double tau =
        target > s.rotor_speeds(i) ? vehicle_.motor_time_constant_up_s : vehicle_.motor_time_constant_down_s;
    d.rotor_speeds(i) = (target - s.rotor_speeds(i)) / tau;
  }
  return d;
}

RigidBodyState MultirotorDynamics::advanced(const RigidBodyState& s, const Derivative& d, double h) {
  RigidBodyState out;
  out.position = s.position + h * d.position;
  out.velocity = s.velocity + h * d.velocity;
  out.orientation.coeffs() = s.orientation.coeffs() + h * d.orientation;
  out.angular_velocity = s.angular_velocity + h * d.angular_velocity;
  out.rotor_speeds = s.rotor_speeds + h * d.rotor_speeds;
  return out;
}

void MultirotorDynamics::step(RigidBodyState& s, const Eigen::VectorXd& commanded, const Environment& env,
                              double dt) const {
  const Derivative k1 = derivative(s, commanded, env);
  const Derivative k2 = derivative(advanced(s, k1, dt / 2), commanded, env);
  const Derivative k3 = derivative(advanced(s, k2, dt / 2), commanded, env);
  const Derivative k4 = derivative(advanced(s, k3, dt), commanded, env);
  Derivative sum;
  sum.position = k1.position + 2 * k2.position + 2 * k3.position + k4.position;
  sum.velocity = k1.velocity + 2 * k2.velocity + 2 * k3.velocity + k4.velocity;
  sum.orientation = k1.orientation + 2 * k2.orientation + 2 * k3.orientation + k4.orientation;
  sum.angular_velocity = k1.angular_velocity + 2 * k2.angular_velocity + 2 * k3.angular_velocity + k4.angular_velocity;
  sum.rotor_speeds = k1.rotor_speeds + 2 * k2.rotor_speeds + 2 * k3.rotor_speeds + k4.rotor_speeds;
  s = advanced(s, sum, dt / 6);
  s.orientation.normalize();  // RK4 drifts off the unit sphere by O(dt^5) a step
  contact(s, env);
}

// A rigid, flat ground: the vehicle never goes below it. Resting on it (the rotors cannot lift
// it), it stays put, level, with its heading kept; a touchdown stops it, as skids would.
void MultirotorDynamics::contact(RigidBodyState& s, const Environment& env) const {
  on_ground_ = false;
  if (!(s.position.z() <= env.ground_z)) return;
  s.position.z() = env.ground_z;
  const Eigen::Vector3d lift = s.orientation * rotor_wrench(s, env.wind).force;
  if (lift.z() > vehicle_.mass_kg * env.gravity && s.velocity.z() >= 0.0) return;  // taking off
  on_ground_ = true;
  s.velocity.setZero();
  s.angular_velocity.setZero();
  s.orientation = Eigen::AngleAxisd(geometry::yaw_of(s.orientation), Eigen::Vector3d::UnitZ());
}

}  // namespace kestrel::vehicle
