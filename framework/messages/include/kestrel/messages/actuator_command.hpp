#pragma once
// What a controller sends to the vehicle: collective thrust and body torques, and the rotor
// speeds they map to for a given mixer.
#include <Eigen/Core>
#include <vector>

#include "kestrel/message.hpp"

namespace kestrel::msg {

struct ActuatorCommand {
  Time stamp{0};
  double thrust_n = 0.0;                                ///< along body z
  Eigen::Vector3d torque_nm = Eigen::Vector3d::Zero();  ///< body frame
  std::vector<double> rotor_speeds_rad_s;               ///< empty if the vehicle takes wrench input
};

}  // namespace kestrel::msg

KESTREL_MESSAGE(kestrel::msg::ActuatorCommand, "kestrel.ActuatorCommand",
                "collective thrust, body torques and rotor speeds");
