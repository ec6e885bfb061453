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
KESTREL_MESSAGE_FIELDS(kestrel::msg::ActuatorCommand, {"stamp", "Time", "ns", "", "time of the command"},
                       {"thrust_n", "double", "N", "body", "collective thrust along body z"},
                       {"torque_nm", "Eigen::Vector3d", "N m", "body", "body torques"},
                       {"rotor_speeds_rad_s", "vector<double>", "rad/s", "",
                        "rotor speeds for the vehicle's mixer; empty when it takes thrust and torques"});
