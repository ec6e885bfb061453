#pragma once
// One inertial measurement: body rates, specific force, and where the sensor fuses them, its
// orientation and the magnetic field, all in the sensor's own frame.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>
#include <string>

#include "kestrel/message.hpp"

namespace kestrel::msg {

struct Imu {
  Time stamp{0};  ///< measurement time on the run clock
  std::string frame = "imu";
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();     ///< rad/s
  Eigen::Vector3d linear_acceleration = Eigen::Vector3d::Zero();  ///< m/s^2
  bool gravity_removed = false;                   ///< false: the specific force, gravity included (1 g up at rest)
  std::optional<Eigen::Quaterniond> orientation;  ///< sensor to its reference frame, when fused
  std::optional<Eigen::Vector3d> magnetic_field;  ///< tesla, when measured
};

}  // namespace kestrel::msg

KESTREL_MESSAGE(kestrel::msg::Imu, "kestrel.Imu", "body rates, acceleration, orientation and magnetic field of an IMU");
KESTREL_MESSAGE_FIELDS(kestrel::msg::Imu, {"stamp", "Time", "ns", "", "measurement time"},
                       {"frame", "string", "", "", "the sensor's frame"},
                       {"angular_velocity", "Eigen::Vector3d", "rad/s", "sensor", "body rates"},
                       {"linear_acceleration", "Eigen::Vector3d", "m/s^2", "sensor",
                        "specific force (gravity included unless gravity_removed)"},
                       {"gravity_removed", "bool", "", "", "whether gravity was taken out of the acceleration"},
                       {"orientation", "optional<Eigen::Quaterniond>", "", "sensor to reference",
                        "fused orientation, when the sensor gives one"},
                       {"magnetic_field", "optional<Eigen::Vector3d>", "T", "sensor", "magnetic field, when measured"});
