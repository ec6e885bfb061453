#pragma once
// A command for a vehicle that runs its own attitude loop (an autopilot): where the body should
// point, how fast it should turn, and how hard to push. The same command as rotor speeds, one
// level lower, is an ActuatorCommand.
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "kestrel/message.hpp"

namespace kestrel::msg {

struct AttitudeTarget {
  Time stamp{0};
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  ///< desired attitude, body to world
  Eigen::Vector3d body_rates = Eigen::Vector3d::Zero();             ///< desired, body frame, rad/s
  double thrust_n = 0.0;                                            ///< collective, along body z
  double hover_thrust_n = 0.0;  ///< the thrust that balances gravity, to normalise thrust_n for an autopilot
};

}  // namespace kestrel::msg

KESTREL_MESSAGE(kestrel::msg::AttitudeTarget, "kestrel.AttitudeTarget",
                "desired attitude, body rates and collective thrust (for an autopilot's attitude loop)");
KESTREL_MESSAGE_FIELDS(kestrel::msg::AttitudeTarget, {"stamp", "Time", "ns", "", "time of the command"},
                       {"orientation", "Eigen::Quaterniond", "", "body to world", "desired attitude"},
                       {"body_rates", "Eigen::Vector3d", "rad/s", "body", "desired body rates"},
                       {"thrust_n", "double", "N", "body", "collective thrust along body z"},
                       {"hover_thrust_n", "double", "N", "", "thrust that balances gravity (m g)"});
