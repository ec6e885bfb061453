#pragma once
// Rotor speeds for a body wrench within the motors' range. The minimum-norm allocation alone asks
// for more than the motors give whenever a hard manoeuvre needs both much thrust and much torque.
// Two ways out:
//   clip      each rotor clipped to its range (RotorS, and so the paper): the thrust stays, the
//             torque is lost, and the attitude overshoots its limit (a hunter braking at 8 m/s^2
//             tilted past 90 degrees);
//   attitude  as PX4's mixer: the collective thrust gives way first, then the yaw torque, then
//             roll and pitch together; the attitude holds, the hunter accelerates less.
#include <Eigen/Core>

#include "kestrel/vehicle/multirotor.hpp"

namespace kestrel::vehicle {

class RotorMixer {
 public:
  enum class Priority { clip, attitude };

  explicit RotorMixer(const Multirotor& vehicle, Priority priority = Priority::clip);

  struct Mix {
    Eigen::VectorXd speeds;  ///< rad/s, each within [0, max_rotor_speed_rad_s]
    double thrust_n = 0.0;   ///< attitude: the thrust the speeds give; clip: the one asked for
    Eigen::Vector3d torque_nm = Eigen::Vector3d::Zero();  ///< the same for the torque
    bool saturated = false;                               ///< the wrench asked for was not the one given
  };

  /// Rotor speeds for `torque_nm` and `thrust_n`: the wanted wrench when it is within reach.
  /// Beyond it, clip: each rotor clipped; attitude: the thrust moved (up or down) as little as
  /// keeps the torque, else the yaw torque shortened, else the roll and pitch torque shortened
  /// (its direction kept) with no yaw.
  Mix mix(const Eigen::Vector3d& torque_nm, double thrust_n) const;

 private:
  Eigen::MatrixXd torque_map_;  ///< rotors x 3: squared speeds per N m of torque
  Eigen::VectorXd thrust_map_;  ///< rotors: squared speeds per N of thrust
  double max_squared_;
  Priority priority_;
  bool shiftable_;  ///< every rotor shares the thrust, so shifting it moves all
};

}  // namespace kestrel::vehicle
