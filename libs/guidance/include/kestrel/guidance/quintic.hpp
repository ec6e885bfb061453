#pragma once
// The minimum-jerk path between two states: a quintic in time per axis that leaves a position,
// velocity and acceleration and arrives at others after a given time. A planner flies the hunter
// to a launch along it, arriving level (at the acceleration asked for) rather than tilted.
#include <Eigen/Core>

namespace kestrel::guidance {

class Quintic {
 public:
  /// From (p0, v0, a0) at 0 to (p1, v1, a1) at `duration` > 0.
  static Quintic between(const Eigen::Vector3d& p0, const Eigen::Vector3d& v0, const Eigen::Vector3d& a0,
                         const Eigen::Vector3d& p1, const Eigen::Vector3d& v1, const Eigen::Vector3d& a1,
                         double duration);
  Eigen::Vector3d position(double t) const;
  Eigen::Vector3d velocity(double t) const;
  Eigen::Vector3d acceleration(double t) const;
  double duration() const { return duration_; }

 private:
  Eigen::Matrix<double, 3, 6> c_ = Eigen::Matrix<double, 3, 6>::Zero();  // p(t) = sum c_k t^k
  double duration_ = 0.0;
};

}  // namespace kestrel::guidance
