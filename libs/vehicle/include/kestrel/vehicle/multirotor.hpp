#pragma once
// A multirotor's physical description, shared by the simulator that flies it and the controller
// that commands it: mass, inertia, where the rotors sit and how a rotor speed turns into thrust
// and drag torque. Defaults are RotorS' Firefly (AscTec Firefly hexacopter).
//
// Body frame FLU (x forward, y left, z up). Rotor i sits at angle_i from body x in the x-y plane,
// arm_length from the centre, spins about body z in `direction` (+1 counter-clockwise seen from
// above) and produces thrust F_i = thrust_constant * w_i^2 along body z and a drag torque
// -direction * moment_constant * F_i about body z.
#include <Eigen/Core>
#include <vector>

namespace kestrel::vehicle {

struct Rotor {
  double angle_rad = 0.0;
  double arm_length_m = 0.215;
  int direction = 1;  ///< +1 counter-clockwise seen from above, -1 clockwise
};

struct Multirotor {
  double mass_kg = 1.56779;
  Eigen::Vector3d inertia_kg_m2{0.0347563, 0.0458929, 0.0977};  ///< diagonal, body axes
  std::vector<Rotor> rotors;
  double thrust_constant = 8.54858e-6;  ///< N / (rad/s)^2
  double moment_constant = 0.016;       ///< m: drag torque per newton of thrust
  double motor_time_constant_up_s = 0.0125;
  double motor_time_constant_down_s = 0.025;
  double max_rotor_speed_rad_s = 838.0;
  double rotor_drag_coefficient = 8.06428e-5;  ///< N s / m per rad/s: drag against airspeed across the disc

  /// The Firefly: six rotors at 30 + k*60 degrees, alternating direction, arm 0.215 m.
  static Multirotor firefly();
  /// `count` rotors evenly spaced from `first_angle_rad`, alternating direction from +1.
  static std::vector<Rotor> ring(int count, double first_angle_rad, double arm_length_m);

  /// Maps squared rotor speeds to the body wrench [torque_x, torque_y, torque_z, thrust]:
  /// wrench = wrench_matrix() * w.^2 (4 x rotors).
  Eigen::MatrixXd wrench_matrix() const;
  /// Minimum-norm squared rotor speeds for a wrench: the right pseudo-inverse of wrench_matrix()
  /// (rotors x 4). Computed here once, for the simulator and the controllers alike.
  Eigen::MatrixXd allocation_inverse() const;
  /// Thrust with every rotor at its top speed, N.
  double max_thrust_n() const;
  /// That thrust over the weight.
  double thrust_to_weight(double gravity = 9.81) const { return max_thrust_n() / (mass_kg * gravity); }
  /// Rotor speed of each rotor when all share the thrust that balances gravity.
  double hover_rotor_speed_rad_s(double gravity = 9.81) const;
};

}  // namespace kestrel::vehicle
