#pragma once
// When to fire: the miss the net would make if fired now, on the launcher's ballistics against
// the target's predicted motion, and the trigger that fires once that miss has held within the
// net's radius.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <kestrel/geometry/frames.hpp>
#include <kestrel/guidance/target_motion.hpp>
#include <optional>

#include "kestrel/net/net_model.hpp"

namespace kestrel::aim {

using guidance::TargetMotion;

/// The miss if the net were fired now: the least distance between the net's centre, on the
/// launcher's own ballistics (`net`), and the predicted target, over the time the net is open.
double predicted_miss(const net::NetModel& net, const geometry::CameraPose& launcher,
                      const Eigen::Vector3d& launcher_velocity, const TargetMotion& target);

/// Decides when to fire: the predicted miss has stayed within the capture radius for the dwell
/// time (0: fire the moment it is), and the last shot is at least the cooldown ago.
class FireTrigger {
 public:
  FireTrigger(double capture_radius_m, double dwell_s, double cooldown_s);
  /// The predicted miss at time t (seconds), or none (no target). True when the net is to be
  /// fired now.
  bool update(double t, std::optional<double> miss_m) { return update(t, miss_m, radius_); }
  /// The same with another radius for this instant (a tighter one for the last net).
  bool update(double t, std::optional<double> miss_m, double radius_m);

 private:
  double radius_, dwell_, cooldown_;
  double within_since_ = -1.0;
  double last_fire_ = -1e300;
};

}  // namespace kestrel::aim
