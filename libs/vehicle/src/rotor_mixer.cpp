#include "kestrel/vehicle/rotor_mixer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace kestrel::vehicle {

namespace {

// The thrusts (N) for which every rotor's squared speed lies in [0, max]: u_i = t_i + c_i T.
struct Range {
  double low = -std::numeric_limits<double>::infinity(), high = std::numeric_limits<double>::infinity();
  bool empty() const { return low > high; }
};

Range thrust_range(const Eigen::VectorXd& torque_part, const Eigen::VectorXd& thrust_map, double max_squared) {
  Range r;
  for (Eigen::Index i = 0; i < torque_part.size(); ++i) {
    r.low = std::max(r.low, -torque_part(i) / thrust_map(i));
    r.high = std::min(r.high, (max_squared - torque_part(i)) / thrust_map(i));
  }
  return r;
}

// The largest s in [0, 1] whose torque s * scaled + fixed leaves some thrust within range (the
// feasible s form an interval from 0, since the constraints are linear in s and T).
double largest_share(const Eigen::VectorXd& fixed, const Eigen::VectorXd& scaled, const Eigen::VectorXd& thrust_map,
                     double max_squared) {
  if (!thrust_range(fixed + scaled, thrust_map, max_squared).empty()) return 1.0;
  double low = 0.0, high = 1.0;
  for (int i = 0; i < 40; ++i) {
    const double mid = 0.5 * (low + high);
    (thrust_range(fixed + mid * scaled, thrust_map, max_squared).empty() ? high : low) = mid;
  }
  return low;
}

}  // namespace

RotorMixer::RotorMixer(const Multirotor& vehicle, Priority priority)
    : max_squared_(vehicle.max_rotor_speed_rad_s * vehicle.max_rotor_speed_rad_s), priority_(priority) {
  const Eigen::MatrixXd allocation = vehicle.allocation_inverse();
  torque_map_ = allocation.leftCols<3>();
  thrust_map_ = allocation.col(3);
  shiftable_ = (thrust_map_.array() > 0.0).all();
}

RotorMixer::Mix RotorMixer::mix(const Eigen::Vector3d& torque_nm, double thrust_n) const {
  Mix out;
  Eigen::Vector3d torque = torque_nm;
  double thrust = thrust_n;
  Eigen::VectorXd squared = torque_map_ * torque + thrust_map_ * thrust;
  const bool within = (squared.array() >= 0.0).all() && (squared.array() <= max_squared_).all();
  if (!within && priority_ == Priority::attitude && shiftable_) {
    // Yaw gives way before roll and pitch: a hunter turning late flies on, one that cannot hold
    // its tilt does not.
    const Eigen::VectorXd roll_pitch = torque_map_.leftCols<2>() * torque.head<2>();
    const Eigen::VectorXd yaw = torque_map_.col(2) * torque.z();
    const double yaw_share = largest_share(roll_pitch, yaw, thrust_map_, max_squared_);
    if (yaw_share < 1.0) {
      torque.z() *= yaw_share;
      if (yaw_share == 0.0)
        torque.head<2>() *=
            largest_share(Eigen::VectorXd::Zero(roll_pitch.size()), roll_pitch, thrust_map_, max_squared_);
    }
    const Range range = thrust_range(torque_map_ * torque, thrust_map_, max_squared_);
    thrust = std::clamp(thrust, range.low, range.high);
    squared = torque_map_ * torque + thrust_map_ * thrust;
  }
  out.speeds = squared.cwiseMax(0.0).cwiseMin(max_squared_).cwiseSqrt();
  out.saturated = !within;
  out.thrust_n = thrust;
  out.torque_nm = torque;
  return out;
}

}  // namespace kestrel::vehicle
