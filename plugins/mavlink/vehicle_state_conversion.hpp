#pragma once
// A vehicle's MAVLink state (NED world, FRD body) as kestrel's VehicleState (ENU world, FLU body),
// every sign flipped in kestrel/geometry/ned_enu.hpp. The stamp is left to the caller.
#include <kestrel/messages/vehicle_state.hpp>
#include <optional>

#include "kestrel/mavlink/messages.hpp"

namespace kestrel::mavlink {

/// LOCAL_POSITION_NED (position, velocity) with ATTITUDE_QUATERNION (attitude, body rates).
msg::VehicleState vehicle_state(const LocalPositionNed& position, const AttitudeQuaternion& attitude);

/// ODOMETRY with its pose in LOCAL_NED and its velocity in BODY_FRD or LOCAL_NED; nullopt for other
/// frames, or a quaternion that is not a rotation.
std::optional<msg::VehicleState> vehicle_state(const Odometry& odometry);

}  // namespace kestrel::mavlink
