#pragma once
// When to fire: the miss the net would make if fired now, on the launcher's ballistics against
// the target's predicted motion, the probability that the open net holds the target, and the
// trigger that fires once the shot has held good.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <functional>
#include <kestrel/geometry/frames.hpp>
#include <kestrel/guidance/target_motion.hpp>
#include <optional>
#include <vector>

#include "kestrel/net/net_model.hpp"

namespace kestrel::aim {

using guidance::TargetMotion;

/// The predicted target minus the net's centre (world) at `tau_s` after the launch.
struct MissAt {
  double tau_s = 0.0;
  Eigen::Vector3d miss = Eigen::Vector3d::Zero();
};

/// The shot if the net were fired now: the closest approach between the net's centre, on the
/// launcher's own ballistics (`net`), and the predicted target, over the time the net is open.
struct PredictedShot {
  double time_s = 0.0;                             ///< after the launch
  Eigen::Vector3d miss = Eigen::Vector3d::Zero();  ///< target minus net centre then (world)
  std::vector<MissAt> path;                        ///< the miss every 10 ms at most while the net is open
};
PredictedShot predict_shot(const net::NetModel& net, const geometry::CameraPose& launcher,
                           const Eigen::Vector3d& launcher_velocity,
                           const std::function<Eigen::Vector3d(double)>& target_at);
/// The same against a target at constant acceleration.
inline PredictedShot predict_shot(const net::NetModel& net, const geometry::CameraPose& launcher,
                                  const Eigen::Vector3d& launcher_velocity, const TargetMotion& target) {
  return predict_shot(net, launcher, launcher_velocity, [&](double tau) { return target.at(tau); });
}

/// Its distance: the predicted miss.
inline double predicted_miss(const net::NetModel& net, const geometry::CameraPose& launcher,
                             const Eigen::Vector3d& launcher_velocity, const TargetMotion& target) {
  return predict_shot(net, launcher, launcher_velocity, target).miss.norm();
}

/// How far the predicted target may be from where it flies: the estimate's uncertainty about its
/// position and velocity, and an acceleration it does not foresee (a manoeuvre while the net flies).
struct ShotUncertainty {
  /// Covariance of [position (m), velocity (m/s)] at the estimate's time, world frame.
  Eigen::Matrix<double, 6, 6> position_velocity = Eigen::Matrix<double, 6, 6>::Zero();
  double lead_s = 0.0;  ///< from the estimate's time to the launch
  /// An acceleration expected to go on (world; a share of the estimate's): it moves the predicted
  /// path by a s^2 / 2.
  Eigen::Vector3d acceleration_m_s2 = Eigen::Vector3d::Zero();
  double manoeuvre_m_s2 = 0.0;  ///< standard deviation per axis of the unforeseen acceleration, held from
                                ///< the estimate's time to the net's closing
};

/// The probability that the open net holds the target: the share of the target's distribution
/// whose path comes within `radius_m` of the net's centre at some instant of the open window.
/// The path is the shot's predicted miss moved by the expected acceleration's a0 s^2 / 2, and each
/// draw moves it further by dp + dv s + a s^2 / 2 (s = lead_s + tau): a draw that
/// is early or late is still caught while the net sweeps through its path, one that drifts away
/// from the net's path is not. A fixed set of 2048 normal draws (the same answer every time).
double hit_probability(const PredictedShot& shot, const ShotUncertainty& uncertainty, double radius_m);

/// Decides when to fire: the predicted miss has stayed within the capture radius for the dwell
/// time (0: fire the moment it is), and the last shot is at least the cooldown ago.
class FireTrigger {
 public:
  FireTrigger(double capture_radius_m, double dwell_s, double cooldown_s);
  /// The predicted miss at time t (seconds), or none (no target). True when the net is to be
  /// fired now.
  bool update(double t, std::optional<double> miss_m) { return update(t, miss_m, radius_); }
  /// The same with another radius for this instant (a tighter one for the last net).
  bool update(double t, std::optional<double> miss_m, double radius_m) {
    return decide(t, miss_m && *miss_m <= radius_m);
  }
  /// The trigger itself, on a shot the caller has judged (good: worth a net now).
  bool decide(double t, bool good_shot);

 private:
  double radius_, dwell_, cooldown_;
  double within_since_ = -1.0;
  double last_fire_ = -1e300;
};

}  // namespace kestrel::aim
