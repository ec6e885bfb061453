#include "kestrel/vehicle/simulated_multirotor.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <kestrel/error.hpp>
#include <limits>

namespace kestrel::vehicle {

SimulatedMultirotor::SimulatedMultirotor(const Multirotor& vehicle, const SimulationConfig& config, std::uint64_t seed)
    : dynamics_(vehicle),
      wind_(config.wind_m_s, config.gust_std_m_s, config.gust_time_constant_s, seed),
      mixer_(vehicle),
      step_(1.0 / config.integration_hz) {
  env_.gravity = config.gravity_m_s2;
  env_.ground_z = config.ground ? config.ground_z_m : -std::numeric_limits<double>::infinity();
  env_.wind = wind_.current();
  state_.position = config.initial_position_m;
  if (config.ground && state_.position.z() < config.ground_z_m) state_.position.z() = config.ground_z_m;
  state_.orientation = Eigen::AngleAxisd(config.initial_yaw_deg * M_PI / 180.0, Eigen::Vector3d::UnitZ());
  const auto rotors = static_cast<Eigen::Index>(vehicle.rotors.size());
  state_.rotor_speeds = Eigen::VectorXd::Zero(rotors);
  command_ = Eigen::VectorXd::Zero(rotors);
  was_on_ground_ = config.ground && state_.position.z() <= config.ground_z_m;
}

void SimulatedMultirotor::command_rotor_speeds(const Eigen::VectorXd& speeds) {
  if (speeds.size() != command_.size())
    throw Error(fmt::format("command has {} rotor speeds; this vehicle has {} rotors", speeds.size(), command_.size()));
  if (!speeds.allFinite()) throw Error("command holds a rotor speed that is not a finite number");
  command_ = speeds;
}

void SimulatedMultirotor::command_wrench(double thrust_n, const Eigen::Vector3d& torque_nm) {
  if (!std::isfinite(thrust_n) || !torque_nm.allFinite())
    throw Error("wrench command holds a thrust or torque that is not a finite number");
  command_rotor_speeds(mixer_.mix(torque_nm, thrust_n).speeds);
}

double SimulatedMultirotor::max_thrust_n() const { return dynamics_.vehicle().max_thrust_n(); }

void SimulatedMultirotor::advance_to(double t_s, const std::function<void(double)>& before_step) {
  while (simulated_ + step_ <= t_s + 1e-12) {
    if (before_step) before_step(simulated_);
    env_.wind = wind_.advance(step_);
    dynamics_.step(state_, command_, env_, step_);
    simulated_ += step_;
    account(step_);
  }
  if (!state_.position.allFinite() || !state_.orientation.coeffs().allFinite())
    throw Error(fmt::format("the simulated vehicle's state is no longer finite at t = {:.3f} s", t_s));
}

msg::VehicleState SimulatedMultirotor::vehicle_state(Time stamp) const {
  msg::VehicleState s;
  s.stamp = stamp;
  s.position = state_.position;
  s.velocity = state_.velocity;
  s.orientation = state_.orientation;
  s.angular_velocity = state_.angular_velocity;
  return s;
}

void SimulatedMultirotor::account(double dt) {
  const bool grounded = dynamics_.on_ground();
  if (grounded && !was_on_ground_) ++record_.touchdowns;
  was_on_ground_ = grounded;
  if (grounded) return;
  record_.flight_time_s += dt;
  record_.distance_m += state_.velocity.norm() * dt;
  record_.max_speed_m_s = std::max(record_.max_speed_m_s, state_.velocity.norm());
  const double tilt = std::acos(std::clamp((state_.orientation * Eigen::Vector3d::UnitZ()).z(), -1.0, 1.0));
  record_.max_tilt_deg = std::max(record_.max_tilt_deg, tilt * 180.0 / M_PI);
}

void report_flight(Context& ctx, const SimulatedMultirotor& flight, ReportSection section,
                   const std::string& more_summary) {
  const std::string id = ctx.id();
  const FlightRecord& r = flight.record();
  const Eigen::Vector3d& p = flight.state().position;
  section.quantity("flight_time_s", r.flight_time_s, "s")
      .quantity("distance_m", r.distance_m, "m")
      .quantity("max_speed_m_s", r.max_speed_m_s, "m/s")
      .quantity("max_tilt_deg", r.max_tilt_deg, "deg")
      .quantity("touchdowns", r.touchdowns)
      .quantity("final_position_m", {{"x", p.x()}, {"y", p.y()}, {"z", p.z()}}, "m")
      .markdown(fmt::format("{:.1f} s in the air, {:.1f} m flown, top speed {:.2f} m/s, largest tilt "
                            "{:.1f} deg, {} touchdown(s).\n{}",
                            r.flight_time_s, r.distance_m, r.max_speed_m_s, r.max_tilt_deg, r.touchdowns,
                            more_summary));
  ctx.set_report_section(id, section);
}

}  // namespace kestrel::vehicle
