#pragma once
// A point on a desired trajectory, as a position controller consumes it.
#include <Eigen/Core>

#include "kestrel/message.hpp"

namespace kestrel::msg {

struct TrajectorySetpoint {
  Time stamp{0};
  Eigen::Vector3d position = Eigen::Vector3d::Zero();      ///< world frame, metres
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();      ///< m/s
  Eigen::Vector3d acceleration = Eigen::Vector3d::Zero();  ///< m/s^2
  double yaw = 0.0;                                        ///< rad
  double yaw_rate = 0.0;                                   ///< rad/s
};

}  // namespace kestrel::msg

KESTREL_MESSAGE(kestrel::msg::TrajectorySetpoint, "kestrel.TrajectorySetpoint",
                "desired position, velocity, acceleration and yaw");
KESTREL_MESSAGE_FIELDS(kestrel::msg::TrajectorySetpoint, {"stamp", "Time", "ns", "", "when the setpoint applies"},
                       {"position", "Eigen::Vector3d", "m", "world", "desired position"},
                       {"velocity", "Eigen::Vector3d", "m/s", "world", "desired velocity (feed-forward)"},
                       {"acceleration", "Eigen::Vector3d", "m/s^2", "world", "desired acceleration (feed-forward)"},
                       {"yaw", "double", "rad", "world", "desired heading about world z"},
                       {"yaw_rate", "double", "rad/s", "world", "desired heading rate"});
