#include "kestrel/vehicle/multirotor.hpp"

#include <Eigen/QR>
#include <cmath>

#include "kestrel/vehicle/multirotor_config.hpp"

namespace kestrel::vehicle {

std::vector<Rotor> Multirotor::ring(int count, double first_angle_rad, double arm_length_m) {
  std::vector<Rotor> rotors;
  for (int k = 0; k < count; ++k)
    rotors.push_back({first_angle_rad + 2.0 * M_PI * k / count, arm_length_m, k % 2 == 0 ? 1 : -1});
  return rotors;
}

Multirotor Multirotor::firefly() {
  Multirotor m;
  m.rotors = ring(6, M_PI / 6.0, 0.215);
  return m;
}

Eigen::MatrixXd Multirotor::wrench_matrix() const {
  Eigen::MatrixXd a(4, static_cast<Eigen::Index>(rotors.size()));
  for (std::size_t i = 0; i < rotors.size(); ++i) {
    const Rotor& r = rotors[i];
    const auto c = static_cast<Eigen::Index>(i);
    // Thrust F along body z at (l cos a, l sin a, 0): torque r x F = (l sin a F, -l cos a F, 0).
    a(0, c) = r.arm_length_m * std::sin(r.angle_rad) * thrust_constant;
    a(1, c) = -r.arm_length_m * std::cos(r.angle_rad) * thrust_constant;
    a(2, c) = -r.direction * moment_constant * thrust_constant;  // reaction to the rotor's drag
    a(3, c) = thrust_constant;
  }
  return a;
}

Eigen::MatrixXd Multirotor::allocation_inverse() const {
  return wrench_matrix().completeOrthogonalDecomposition().pseudoInverse();
}

double Multirotor::max_thrust_n() const {
  return static_cast<double>(rotors.size()) * thrust_constant * max_rotor_speed_rad_s * max_rotor_speed_rad_s;
}

double Multirotor::hover_rotor_speed_rad_s(double gravity) const {
  return std::sqrt(mass_kg * gravity / (thrust_constant * static_cast<double>(rotors.size())));
}

Multirotor MultirotorConfig::multirotor() const {
  const MultirotorConfig defaults{};
  Multirotor m = vehicle::airframe(airframe).body;
  // A field left at its default is the airframe's; one set to anything else replaces it.
  const auto take = [](auto& into, const auto& given, const auto& fallback) {
    if (given != fallback) into = given;
  };
  take(m.mass_kg, mass_kg, defaults.mass_kg);
  take(m.inertia_kg_m2, inertia_kg_m2, defaults.inertia_kg_m2);
  take(m.thrust_constant, thrust_constant, defaults.thrust_constant);
  take(m.moment_constant, moment_constant, defaults.moment_constant);
  take(m.motor_time_constant_up_s, motor_time_constant_up_s, defaults.motor_time_constant_up_s);
  take(m.motor_time_constant_down_s, motor_time_constant_down_s, defaults.motor_time_constant_down_s);
  take(m.max_rotor_speed_rad_s, max_rotor_speed_rad_s, defaults.max_rotor_speed_rad_s);
  take(m.rotor_drag_coefficient, rotor_drag_coefficient, defaults.rotor_drag_coefficient);
  if (rotor_count != defaults.rotor_count || first_rotor_angle_deg != defaults.first_rotor_angle_deg ||
      arm_length_m != defaults.arm_length_m) {
    // The ring is rebuilt from the airframe's own ring with the fields given.
    const Rotor& first = m.rotors.front();
    const int count = rotor_count != defaults.rotor_count ? rotor_count : static_cast<int>(m.rotors.size());
    const double angle = first_rotor_angle_deg != defaults.first_rotor_angle_deg ? first_rotor_angle_deg * M_PI / 180.0
                                                                                 : first.angle_rad;
    const double arm = arm_length_m != defaults.arm_length_m ? arm_length_m : first.arm_length_m;
    m.rotors = Multirotor::ring(count, angle, arm);
  }
  return m;
}

}  // namespace kestrel::vehicle
