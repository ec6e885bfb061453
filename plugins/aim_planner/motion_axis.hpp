#pragma once
// Where round the target the hunter stands. The net sweeps along its own path while it is open,
// so a shot along the target's motion leaves only its manoeuvre across that path to the net's
// radius; a shot across its motion leaves all of it. The target's axis of motion is the principal
// direction of its horizontal velocity, averaged over a time constant; the hunter goes round the
// target on its standoff circle towards that axis, a step ahead of its line of sight at a time,
// so that the camera stays on the target all the way.
#include <Eigen/Core>
#include <optional>

namespace kestrel::aim {

class MotionAxis {
 public:
  explicit MotionAxis(double time_constant_s) : time_constant_s_(time_constant_s) {}
  /// Adds the target's velocity (world frame), dt seconds after the last.
  void update(const Eigen::Vector3d& velocity, double dt);
  /// The axis (unit, horizontal), signed to lie on the side of `bearing` (hunter to target); none
  /// while the target's motion has no clear axis.
  std::optional<Eigen::Vector2d> axis(const Eigen::Vector2d& bearing) const;
  void reset() { moment_.setZero(); }

 private:
  double time_constant_s_;
  Eigen::Matrix2d moment_ = Eigen::Matrix2d::Zero();  // the average of v v^T (horizontal)
};

/// The direction to stand in (from the hunter towards the target, unit, horizontal): `bearing`
/// turned towards `axis` by at most `max_step_rad`.
Eigen::Vector2d approach_direction(const Eigen::Vector2d& bearing, const Eigen::Vector2d& axis, double max_step_rad);

}  // namespace kestrel::aim
