#include "kestrel/guidance/quintic.hpp"

namespace kestrel::guidance {

Quintic Quintic::between(const Eigen::Vector3d& p0, const Eigen::Vector3d& v0, const Eigen::Vector3d& a0,
                         const Eigen::Vector3d& p1, const Eigen::Vector3d& v1, const Eigen::Vector3d& a1,
                         double duration) {
  Quintic q;
  q.duration_ = duration;
  const double T = duration, T2 = T * T, T3 = T2 * T;
  const Eigen::Vector3d h = p1 - p0;
  q.c_.col(0) = p0;
  q.c_.col(1) = v0;
  q.c_.col(2) = 0.5 * a0;
  q.c_.col(3) = (20.0 * h - (8.0 * v1 + 12.0 * v0) * T - (3.0 * a0 - a1) * T2) / (2.0 * T3);
  q.c_.col(4) = (-30.0 * h + (14.0 * v1 + 16.0 * v0) * T + (3.0 * a0 - 2.0 * a1) * T2) / (2.0 * T3 * T);
  q.c_.col(5) = (12.0 * h - 6.0 * (v1 + v0) * T - (a0 - a1) * T2) / (2.0 * T3 * T2);
  return q;
}

Eigen::Vector3d Quintic::position(double t) const {
  return c_.col(0) + t * (c_.col(1) + t * (c_.col(2) + t * (c_.col(3) + t * (c_.col(4) + t * c_.col(5)))));
}

Eigen::Vector3d Quintic::velocity(double t) const {
  return c_.col(1) + t * (2.0 * c_.col(2) + t * (3.0 * c_.col(3) + t * (4.0 * c_.col(4) + t * 5.0 * c_.col(5))));
}

Eigen::Vector3d Quintic::acceleration(double t) const {
  return 2.0 * c_.col(2) + t * (6.0 * c_.col(3) + t * (12.0 * c_.col(4) + t * 20.0 * c_.col(5)));
}

}  // namespace kestrel::guidance
