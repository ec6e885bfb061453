#pragma once
// When to fire: the miss the net would make if fired now, on the launcher's ballistics against
// the target's predicted motion, and the trigger that fires once that miss has held within the
// net's radius.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <functional>
#include <kestrel/geometry/frames.hpp>
#include <kestrel/guidance/target_motion.hpp>
#include <optional>

#include "kestrel/net/net_model.hpp"

namespace kestrel::aim {

using guidance::TargetMotion;

/// The shot if the net were fired now: the closest approach between the net's centre, on the
/// launcher's own ballistics (`net`), and the predicted target, over the time the net is open.
struct PredictedShot {
  double time_s = 0.0;                             ///< after the launch
  Eigen::Vector3d miss = Eigen::Vector3d::Zero();  ///< target minus net centre then (world)
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

/// The probability that the net holds the target: that the target, at `miss` from the net's
/// centre with a Gaussian error of `covariance` about it, lies within `radius_m` of the centre.
/// A fixed set of 2048 standard normal points (no state, the same answer every time).
double hit_probability(const Eigen::Vector3d& miss, const Eigen::Matrix3d& covariance, double radius_m);

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
