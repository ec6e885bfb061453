#include "kestrel/vehicle/airframe.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <kestrel/error.hpp>

namespace kestrel::vehicle {

namespace {

Airframe firefly() {
  Airframe a;
  a.name = "firefly";
  a.body = Multirotor::firefly();
  // RotorS' Firefly gains (lee_controller_firefly.yaml); the envelope the benchmark flies it in:
  // 8 m/s^2 at level height is a 39 degree tilt, well inside its 2.3 thrust-to-weight.
  a.envelope = {12.0, 8.0, 60.0};
  return a;
}

// A 1 kg quadrotor in X, 0.12 m arms, motors of 2800 rad/s at 11 N each: thrust-to-weight 4.5.
// Gains place the loops on the lighter body: position w_n = 3 rad/s (twice the Firefly's pull
// per kilogram), attitude w_n = 14 rad/s, yaw 3 rad/s, each damped about 0.8.
Airframe interceptor() {
  Airframe a;
  a.name = "interceptor";
  Multirotor& m = a.body;
  m.mass_kg = 1.0;
  m.inertia_kg_m2 = {0.0065, 0.0065, 0.012};
  m.rotors = Multirotor::ring(4, M_PI / 4.0, 0.12);
  m.thrust_constant = 1.408e-6;
  m.moment_constant = 0.016;
  m.motor_time_constant_up_s = 0.01;
  m.motor_time_constant_down_s = 0.02;
  m.max_rotor_speed_rad_s = 2800.0;
  m.rotor_drag_coefficient = 4.0e-5;
  a.gains.position = {9.0, 9.0, 9.0};
  a.gains.velocity = {4.8, 4.8, 4.8};
  a.gains.attitude = {1.27, 1.27, 0.108};
  a.gains.angular_rate = {0.146, 0.146, 0.058};
  a.envelope = {20.0, 12.0, 60.0};
  return a;
}

const std::vector<Airframe>& airframes() {
  static const std::vector<Airframe> all{firefly(), interceptor()};
  return all;
}

}  // namespace

const Airframe& airframe(std::string_view name) {
  for (const Airframe& a : airframes())
    if (a.name == name) return a;
  throw Error(fmt::format("unknown airframe '{}' (known: {})", name, fmt::join(airframe_names(), ", ")));
}

std::vector<std::string> airframe_names() {
  std::vector<std::string> names;
  for (const Airframe& a : airframes()) names.push_back(a.name);
  return names;
}

}  // namespace kestrel::vehicle
