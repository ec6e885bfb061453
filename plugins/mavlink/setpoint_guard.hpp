#pragma once
// What the sink lets through to the autopilot, whatever arrives from upstream: finite numbers
// only, positions inside the geofence box, speeds and tilts within their limits. Each refusal and
// each clamp is counted for the report.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <kestrel/messages/attitude_target.hpp>
#include <kestrel/messages/trajectory_setpoint.hpp>
#include <optional>

namespace kestrel::mavlink {

struct GuardLimits {
  Eigen::Vector3d fence_min{-50.0, -50.0, 0.5};  ///< ENU, m
  Eigen::Vector3d fence_max{50.0, 50.0, 30.0};
  double max_speed_m_s = 8.0;
  double max_tilt_deg = 35.0;
};

struct GuardCounts {
  std::uint64_t non_finite = 0;     ///< commands refused for a NaN or an infinity
  std::uint64_t fence_clamps = 0;   ///< positions moved back inside the fence
  std::uint64_t speed_clamps = 0;   ///< velocities cut to the speed limit
  std::uint64_t tilt_clamps = 0;    ///< attitudes tipped back to the tilt limit, accelerations cut to it
  std::uint64_t thrust_clamps = 0;  ///< thrusts cut into [0, 1]
};

class SetpointGuard {
 public:
  explicit SetpointGuard(GuardLimits limits) : limits_(limits) {}

  /// The setpoint made safe, or nullopt when any field is not finite.
  std::optional<msg::TrajectorySetpoint> position(const msg::TrajectorySetpoint& in);
  /// The attitude made safe (tilt limited, orientation normalised), or nullopt when not finite.
  std::optional<msg::AttitudeTarget> attitude(const msg::AttitudeTarget& in);
  /// A normalised thrust (thrust_n / (hover_thrust_n / hover_fraction)) clamped to [0, 1].
  double normalised_thrust(const msg::AttitudeTarget& in, double hover_fraction);

  const GuardCounts& counts() const { return counts_; }
  const GuardLimits& limits() const { return limits_; }

 private:
  GuardLimits limits_;
  GuardCounts counts_;
};

}  // namespace kestrel::mavlink
