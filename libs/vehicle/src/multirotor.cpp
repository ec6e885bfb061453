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

double Multirotor::hover_rotor_speed_rad_s(double gravity) const {
  return std::sqrt(mass_kg * gravity / (thrust_constant * static_cast<double>(rotors.size())));
}

Multirotor MultirotorConfig::multirotor() const {
  Multirotor m;
  m.mass_kg = mass_kg;
  m.inertia_kg_m2 = inertia_kg_m2;
  m.rotors = Multirotor::ring(rotor_count, first_rotor_angle_deg * M_PI / 180.0, arm_length_m);
  m.thrust_constant = thrust_constant;
  m.moment_constant = moment_constant;
  m.motor_time_constant_up_s = motor_time_constant_up_s;
  m.motor_time_constant_down_s = motor_time_constant_down_s;
  m.max_rotor_speed_rad_s = max_rotor_speed_rad_s;
  m.rotor_drag_coefficient = rotor_drag_coefficient;
  return m;
}

}  // namespace kestrel::vehicle
