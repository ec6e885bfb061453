#pragma once
// The paper's aim (section 2.4): the net opens best with the intruder at x_E^d = [0, 1, 2] m in
// the camera frame (2 m ahead of the launcher, 1 m below it), so the hunter drives the error
// e_x = x_E^d - x_E to zero. It does so with its position along its heading and its height, and
// with its yaw, which turns the camera onto the intruder: the lateral error is never flown off
// sideways, so the intruder stays in view.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <kestrel/geometry/frames.hpp>
#include <optional>

#include "kestrel/net/net_model.hpp"

namespace kestrel::aim {

struct AimPose {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< hunter body position (world)
  double yaw = 0.0;                                    ///< hunter heading (world, rad)
};

/// Where the hunter must be, level, for an intruder at `intruder_world` to sit at `aim_point_camera`
/// of its camera (mounted at `camera_offset_body`, looking along body x), heading straight at
/// the intruder from `hunter_position`. Keeps `current_yaw` when the intruder is right above or
/// below.
AimPose aim_pose(const Eigen::Vector3d& intruder_world, const Eigen::Vector3d& hunter_position, double current_yaw,
                 const Eigen::Vector3d& aim_point_camera, const Eigen::Vector3d& camera_offset_body);

/// The wrapped difference a - b, in (-pi, pi].
double angle_difference(double a, double b);

/// A smooth reference towards a moving goal: velocity is the goal's own velocity plus a
/// proportional pull, then limited in speed and acceleration; yaw moves at a limited rate. The
/// controller receives the reference, never a jump.
class AimReference {
 public:
  struct Limits {
    double gain = 1.0;              ///< 1/s: pull towards the goal
    double max_speed = 3.0;         ///< m/s
    double max_acceleration = 3.0;  ///< m/s^2
    double max_yaw_rate = 1.0;      ///< rad/s
  };

  AimReference(Limits limits, const Eigen::Vector3d& start, double start_yaw);

  /// Moves the reference dt seconds towards `goal` (moving at `goal_velocity`).
  void advance(const AimPose& goal, const Eigen::Vector3d& goal_velocity, double dt);
  /// Stops where it is (velocity ramps down at the acceleration limit); `yaw_rate` turns it.
  void hold(double dt, double yaw_rate = 0.0);

  const Eigen::Vector3d& position() const { return position_; }
  const Eigen::Vector3d& velocity() const { return velocity_; }
  const Eigen::Vector3d& acceleration() const { return acceleration_; }
  double yaw() const { return yaw_; }
  double yaw_rate() const { return yaw_rate_; }

 private:
  void move(const Eigen::Vector3d& wanted_velocity, double dt);

  Limits limits_;
  Eigen::Vector3d position_, velocity_ = Eigen::Vector3d::Zero(), acceleration_ = Eigen::Vector3d::Zero();
  double yaw_, yaw_rate_ = 0.0;
};

/// A target's predicted motion: position, velocity and acceleration now (world).
struct TargetMotion {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d acceleration = Eigen::Vector3d::Zero();
  Eigen::Vector3d at(double tau) const { return position + velocity * tau + 0.5 * acceleration * tau * tau; }
};

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
  bool update(double t, std::optional<double> miss_m);

 private:
  double radius_, dwell_, cooldown_;
  double within_since_ = -1.0;
  double last_fire_ = -1e300;
};

}  // namespace kestrel::aim
