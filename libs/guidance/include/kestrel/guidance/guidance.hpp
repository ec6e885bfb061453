#pragma once
// Guidance as a component of kind "guidance": the law that chooses how the hunter closes on its
// target, from the aim's world-frame estimate of the target, until it hands over to the terminal
// phase. The terminal phase is the paper's aim law for every law alike (the aim planner drives
// the hunter to the aim pose, x_E^d, with the target's velocity fed forward; the camera faces
// the target) and fires.
//
//   - id: aim
//     type: aim_planner
//     params:
//       guidance: {type: pn, navigation_constant: 4}   # or hold_aim, pursuit, frpn, predictive
//
// Implementations: hold_aim (the paper's), pursuit, pn, frpn, predictive (docs/control.md,
// "Guidance laws").
#include <Eigen/Core>
#include <optional>
#include <string_view>

#include "kestrel/guidance/aim_pose.hpp"
#include "kestrel/guidance/target_futures.hpp"
#include "kestrel/guidance/target_motion.hpp"
#include "kestrel/net/net_model.hpp"

namespace kestrel::guidance {

/// What the hunter can fly: the reference is limited to these, and a law plans within them.
struct FlightLimits {
  double max_speed = 5.0;         ///< m/s
  double max_acceleration = 4.0;  ///< m/s^2
};

/// What a law sees at one instant (world frame).
struct Engagement {
  double dt = 0.0;  ///< s since the previous call (0 on the first)
  /// The reference the setpoint follows: the law commands its velocity.
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d acceleration = Eigen::Vector3d::Zero();
  double yaw = 0.0;
  TargetMotion target;  ///< the aim's estimate of the target
  /// Where the hunter must be now for the target to sit at x_E^d (never below the least altitude).
  AimPose aim;
  AimGeometry geometry;
  FlightLimits limits;
  double min_altitude = 0.0;  ///< m: no aim pose below this
  /// The target's sampled futures, from the estimate's time (none: a law that needs them hands
  /// over to the terminal phase).
  const TargetFutures* futures = nullptr;
  /// The launcher's net (none: as for the futures).
  const net::NetModel* net = nullptr;
  /// The hypothesis that the target reacts to the hunter (none: it does not).
  const ReactionBelief* reaction = nullptr;
};

/// A law's answer: the reference's wanted velocity (limited by the reference) and heading, or
/// the hand-over to the terminal phase.
struct GuidanceCommand {
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  double yaw = 0.0;
  bool terminal = false;  ///< true: the aim planner aligns the net instead (velocity, yaw unused)
  /// A law that plans its launch on the futures: what a later launch is worth, its chance of a
  /// capture discounted for the wait; the fire policy weighs a shot now against it.
  std::optional<double> later_value;
};

class Guidance {
 public:
  static constexpr std::string_view kKind = "guidance";
  virtual ~Guidance() = default;
  virtual GuidanceCommand command(const Engagement& engagement) = 0;
  /// Whether the law reads the target's sampled futures (the aim draws them only then).
  virtual bool needs_futures() const { return false; }
  /// A new target is engaged: forget what was learnt about the last one.
  virtual void reset() {}
};

/// The hand-over shared by the laws other than hold_aim: terminal once the reference is within
/// `handover_m` of the aim pose.
inline bool within_handover(const Engagement& e, double handover_m) {
  return (e.aim.position - e.position).norm() <= handover_m;
}

/// A terminal command.
inline GuidanceCommand terminal_phase() { return {Eigen::Vector3d::Zero(), 0.0, true, std::nullopt}; }

}  // namespace kestrel::guidance
