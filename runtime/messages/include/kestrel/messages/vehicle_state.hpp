#pragma once
// The rigid-body state of a vehicle (odometry).
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "kestrel/message.hpp"

namespace kestrel::msg {

struct VehicleState {
  Time stamp{0};
  Eigen::Vector3d position = Eigen::Vector3d::Zero();               ///< world frame (z up), metres
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();               ///< world frame, m/s
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  ///< body to world
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();       ///< body frame, rad/s
};

}  // namespace kestrel::msg

KESTREL_MESSAGE(kestrel::msg::VehicleState, "kestrel.VehicleState", "vehicle pose, velocity and body rates (odometry)");
KESTREL_MESSAGE_FIELDS(kestrel::msg::VehicleState, {"stamp", "Time", "ns", "", "time of the state"},
                       {"position", "Eigen::Vector3d", "m", "world", "position of the centre of mass"},
                       {"velocity", "Eigen::Vector3d", "m/s", "world", "velocity"},
                       {"orientation", "Eigen::Quaterniond", "", "body to world",
                        "attitude: rotates body-frame vectors into the world frame"},
                       {"angular_velocity", "Eigen::Vector3d", "rad/s", "body", "body rates"});
